// Writing output files without destroying what is at their paths, and all of
// a command's outputs or none of them.
//
// Per path, by what is there:
// - nothing, or a regular file: the bytes go to a temporary file in the same
//   directory (a short name of its own, so any name that fits the file-name
//   limit works), which is renamed over the path once every output of the
//   call was written: a failed run leaves no file and replaces none;
// - a symbolic link: the same for the file it points to (the link stays);
// - anything else (a device such as /dev/null or /dev/full, a FIFO, a
//   socket): written directly, after the temporary files, with every write
//   checked (/dev/full fails with "No space left on device").
// A directory is an error.
#pragma once

#include <string>
#include <vector>

#include "base/result.hpp"

namespace impossible {

struct OutputBytes {
    std::string path;
    std::string bytes;
};

// Writes every file or, on the first failure, removes the temporary files
// and returns "PATH: cannot write: reason" (nothing renamed into place).
Result<void> write_output_files(const std::vector<OutputBytes>& files);

// One file, the same way.
Result<void> write_output_file(const std::string& path, const std::string& bytes);

// What a path names, for telling whether two paths are the same file: the
// device and inode of an existing file (through symbolic links), else the
// absolute, normalised path where it would be created. `shareable` is true
// for character devices (/dev/null, /dev/stdout on a terminal), which several
// outputs may name without harm.
struct FileIdentity {
    bool exists = false;
    unsigned long long device = 0, inode = 0;
    std::string path;  // when !exists
    bool shareable = false;
    bool operator==(const FileIdentity& o) const {
        return exists == o.exists && (exists ? device == o.device && inode == o.inode : path == o.path);
    }
};
FileIdentity identify_file(const std::string& path);

}  // namespace impossible
