#include "core/final_paths.hpp"

#include <cctype>

namespace wifislam {

namespace fs = std::filesystem;

namespace {

bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
}

/// Whether `text` at `at` goes on with the name just before it ("2" after "/out.partial", or
/// ".bak"); a full stop ending a sentence does not.
bool continues_name(const std::string& text, std::size_t at) {
  if (at >= text.size()) return false;
  if (text[at] == '.') return at + 1 < text.size() && name_char(text[at + 1]);
  return name_char(text[at]);
}

}  // namespace

FinalPaths::FinalPaths(const fs::path& staging, const fs::path& final)
    : staging_(fs::absolute(staging).lexically_normal()),
      final_(fs::absolute(final).lexically_normal()) {}

fs::path FinalPaths::of(const fs::path& path) const {
  if (staging_.empty()) return path;
  const fs::path absolute = fs::absolute(path).lexically_normal();
  const fs::path inside = absolute.lexically_relative(staging_);
  if (inside.empty() || *inside.begin() == "..") return path;
  return inside == "." ? final_ : (final_ / inside).lexically_normal();
}

std::string FinalPaths::in_text(std::string text) const {
  if (staging_.empty() || staging_ == final_) return text;
  // A mention is the staging folder itself or a path in it, not a longer name that starts
  // alike ("/out.partial2").
  const std::string from = staging_.string(), to = final_.string();
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
    const std::size_t end = at + from.size();
    if (continues_name(text, end)) {
      at = end;
      continue;
    }
    text.replace(at, from.size(), to);
    at += to.size();
  }
  return text;
}

}  // namespace wifislam
