#pragma once
// "Did you mean" for mistyped keys: the closest known name when it is only a typo away (edit
// distance below 3), used wherever a file or option names a key (scene files, study files).

#include <string>
#include <vector>

namespace wifislam {

/// "; did you mean 'x'?" for the known key closest to `key`, or "" when none is close.
std::string did_you_mean(const std::string& key, const std::vector<std::string>& known);

/// Levenshtein distance (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace wifislam
