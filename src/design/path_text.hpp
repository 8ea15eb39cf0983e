// Path files (cli.md, `walk`): one physical head pose a line, `X Y Z YAW
// PITCH ROLL`, `#` comments and blank lines skipped. The tour writes them
// (layout/path_file.hpp reads them).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "base/result.hpp"
#include "math/pose.hpp"

namespace impossible::design {

// The text of a path file: a comment header, then one pose a line, each
// number with 4 decimals (0.1 mm, 0.0001°). Each note (k, text) is a
// comment line "# text" just before pose k (after the last pose for k ≥
// poses.size()), in the order given.
using PathNote = std::pair<std::size_t, std::string>;
std::string path_text(const std::vector<math::HeadPose>& poses, const std::string& header,
                      const std::vector<PathNote>& notes = {});

}  // namespace impossible::design
