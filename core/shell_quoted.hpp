#pragma once
// Text for a shell command line that a user pastes or a job script runs: a path with a space, a
// quote or a '$' must reach the program as one argument, unchanged.

#include <string>
#include <string_view>

namespace wifislam {

/// Single-quoted for a POSIX shell ('it'\''s'): always one word, whatever it holds.
inline std::string shell_quoted(std::string_view text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// As it is when the shell reads it as one word unchanged (letters, digits and _ - . / : = @ %
/// + ,), else single-quoted: the commands printed for a user stay readable in the usual case.
inline std::string shell_word(std::string_view text) {
  constexpr std::string_view kPlain =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./:=@%+,";
  if (!text.empty() && text.find_first_not_of(kPlain) == std::string_view::npos)
    return std::string(text);
  return shell_quoted(text);
}

}  // namespace wifislam
