#include "floorplan/osm_node_check.hpp"

#include <expat.h>

#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace wifislam::floorplan {

namespace {

struct ParserDeleter {
  void operator()(XML_ParserStruct* parser) const { XML_ParserFree(parser); }
};

struct OsmScan {
  std::string file;
  XML_Parser parser = nullptr;
  std::unordered_set<std::string> nodes;
  std::vector<std::pair<std::string, std::string>> refs;  // (node id, where the way names it)
  std::string way;
  std::exception_ptr error;  // thrown in a handler; expat is C and must not be unwound

  std::string where(std::string_view kind, std::string_view id) const {
    return fmt::format("{}:{} ({}/{})", file, XML_GetCurrentLineNumber(parser), kind, id);
  }
};

/// The value of attribute `name`, or nullptr.
const XML_Char* attribute(const XML_Char** attributes, const char* name) {
  for (int i = 0; attributes[i] != nullptr; i += 2)
    if (std::strcmp(attributes[i], name) == 0) return attributes[i + 1];
  return nullptr;
}

std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

void check_node(const OsmScan& scan, const std::string& id, const XML_Char** attributes) {
  for (const auto& [name, limit_deg] : {std::pair{"lat", 90.0}, std::pair{"lon", 180.0}}) {
    const XML_Char* value = attribute(attributes, name);
    if (value == nullptr) continue;  // the driver's own error
    double degrees = 0;
    if (!parse_double(trimmed(value), degrees) || std::abs(degrees) > limit_deg) {
      throw ParseError(scan.where("node", id), name,
                       fmt::format("'{}': expected a number of degrees in [-{}, {}] (WGS 84)",
                                   value, limit_deg, limit_deg));
    }
  }
}

void on_element(void* data, const XML_Char* name, const XML_Char** attributes) {
  OsmScan& scan = *static_cast<OsmScan*>(data);
  if (scan.error) return;
  try {
    const XML_Char* id = attribute(attributes, "id");
    if (std::strcmp(name, "node") == 0) {
      scan.nodes.insert(id ? id : "");
      check_node(scan, id ? id : "", attributes);
    } else if (std::strcmp(name, "way") == 0) {
      scan.way = id ? id : "";
    } else if (std::strcmp(name, "nd") == 0) {
      const XML_Char* ref = attribute(attributes, "ref");
      scan.refs.emplace_back(ref ? ref : "", scan.where("way", scan.way));
    }
  } catch (...) {
    scan.error = std::current_exception();
    XML_StopParser(scan.parser, XML_FALSE);
  }
}

}  // namespace

void check_osm_nodes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(file.string() + ": cannot be read");
  const std::unique_ptr<XML_ParserStruct, ParserDeleter> parser(XML_ParserCreate(nullptr));
  if (!parser) throw std::bad_alloc();
  OsmScan scan;
  scan.file = file.string();
  scan.parser = parser.get();
  XML_SetUserData(parser.get(), &scan);
  XML_SetStartElementHandler(parser.get(), on_element);
  std::vector<char> chunk(1 << 16);
  bool last = false;
  while (!last) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    if (in.bad()) throw IoError(file.string() + ": cannot be read");
    last = in.eof();
    if (XML_Parse(parser.get(), chunk.data(), static_cast<int>(in.gcount()), last) ==
        XML_STATUS_ERROR) {
      if (scan.error) std::rethrow_exception(scan.error);
      throw ParseError(
          fmt::format("{}:{}:{}", file.string(), XML_GetCurrentLineNumber(parser.get()),
                      XML_GetCurrentColumnNumber(parser.get()) + 1),
          "",
          fmt::format("XML that GDAL's OSM driver cannot read: {}",
                      XML_ErrorString(XML_GetErrorCode(parser.get()))));
    }
  }
  for (const auto& [ref, where] : scan.refs) {
    if (!scan.nodes.count(ref)) {
      throw ParseError(where, "nd ref",
                       "node " + ref + " is not in the file: the way is incomplete");
    }
  }
}

}  // namespace wifislam::floorplan
