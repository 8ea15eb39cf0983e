// The one reading of a number a person wrote on the command line or in a
// path file (docs/cli.md, "Numbers"): decimal, as from_chars reads it, with
// an optional leading '+' (not "+-"); no hexadecimal ("0x40"), no leading
// space, no inf or nan. A number closer to 0 than the smallest normal double
// (2.2e-308: "1e-320", "1e-400") reads as 0.
#pragma once

#include <string>
#include <string_view>

namespace impossible {

struct NumberText {
    double value = 0.0;
    // Empty when `value` holds the number; else why the text is not one,
    // worded to follow the quoted text: "is not a finite number", "is
    // hexadecimal: write numbers in decimal".
    std::string problem;
};

NumberText read_number_text(std::string_view text);

}  // namespace impossible
