#pragma once
// Whether text is valid UTF-8. JSON (run.json, export.json, metrics.json ...) holds only UTF-8:
// a path of other bytes (a Latin-1 file name) given on the command line would otherwise fail
// when the first JSON file naming it is written, after the work.

#include <string_view>

namespace wifislam {

/// True when `text` is well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, nothing
/// above U+10FFFF).
bool is_valid_utf8(std::string_view text);

}  // namespace wifislam
