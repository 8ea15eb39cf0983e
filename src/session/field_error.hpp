// Problems with one setting, in the library's own names, for each front end
// to spell in its own: the command line as its flags (--max-depth), the
// library and Python as the fields of View and RenderOptions (max_depth).
//
// A message may name settings as {field} ("give {room}", "{max_depth} 3");
// spell_fields replaces each with the front end's name for it.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace impossible::session {

struct FieldError {
    enum class Kind {
        Value,    // the field's value is out of range: message starts with the value ("300 is not in 0..250")
        Problem,  // a sentence of its own ("the head is in no room; give {room}")
    };
    Kind kind = Kind::Value;
    std::string field;    // "max_depth", "room", "pose", "size"
    std::string message;  // {field} names other settings
};

// A front end's name for a field: the flag ("--max-depth") or the field itself.
using FieldNamer = std::function<std::string(const std::string& field)>;

// `message` with each {field} replaced by namer(field).
std::string spell_fields(const std::string& message, const FieldNamer& namer);

// The library's and Python's name of a field: its own ("max_depth"), but
// "no_cull" ("cull = false", RenderOptions::cull off).
std::string library_field(const std::string& field);

// The library's and Python's spelling: "max_depth 300 is not in 0..250", or
// the sentence, with {field} as the field's own name.
std::string library_message(const FieldError& error);

// The command line's: "--max-depth: 300 is not in 0..250", or
// "--pose: the head is in no room; give --room".
std::string command_message(const FieldError& error, const FieldNamer& flag_of);

}  // namespace impossible::session
