#include "core/error.hpp"

namespace wifislam {

namespace {
std::string format_parse_error(const std::string& where, const std::string& key_path,
                               const std::string& message) {
  std::string out = where;
  if (!key_path.empty()) out += (out.empty() ? "" : ": ") + std::string("key '") + key_path + "'";
  if (!out.empty()) out += ": ";
  return out + message;
}
}  // namespace

ParseError::ParseError(std::string where, std::string key_path, std::string message)
    : Error(format_parse_error(where, key_path, message)),
      where_(std::move(where)),
      key_path_(std::move(key_path)),
      detail_(std::move(message)) {}

}  // namespace wifislam
