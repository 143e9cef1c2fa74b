#include "floorplan/osm_node_check.hpp"

#include <expat.h>

#include <cctype>
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

/// A way's reference to a node, and whether the node came before it.
struct NodeRef {
  std::string node, where;
  bool node_seen = false;
};

struct OsmScan {
  std::string file;
  XML_Parser parser = nullptr;
  std::unordered_set<std::string> nodes;
  std::vector<NodeRef> refs;
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
      const XML_Char* ref_text = attribute(attributes, "ref");
      const std::string ref = ref_text ? ref_text : "";
      scan.refs.push_back({ref, scan.where("way", scan.way), scan.nodes.count(ref) > 0});
    }
  } catch (...) {
    scan.error = std::current_exception();
    XML_StopParser(scan.parser, XML_FALSE);
  }
}

/// The single-byte encodings GDAL's OSM driver reads beyond expat's own (UTF-8, UTF-16,
/// ISO-8859-1, US-ASCII), as its handler does (ogr/ogr_expat.cpp): windows-1252 and ISO-8859-15,
/// each Latin-1 but for the code points listed.
int on_unknown_encoding(void*, const XML_Char* name, XML_Encoding* info) {
  std::string lower(name);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool windows_1252 = lower == "windows-1252";
  if (!windows_1252 && lower != "iso-8859-15") return XML_STATUS_ERROR;
  for (int i = 0; i < 256; ++i) info->map[i] = i;
  if (windows_1252) {
    static constexpr int k80To9f[32] = {
        0x20AC, -1,     0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
        0x2039, 0x0152, -1,     0x017D, -1,     -1,     0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
        0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, -1,     0x017E, 0x0178};
    for (int i = 0; i < 32; ++i) info->map[0x80 + i] = k80To9f[i];
  } else {
    for (const auto& [byte, code] :
         {std::pair{0xA4, 0x20AC}, std::pair{0xA6, 0x0160}, std::pair{0xA8, 0x0161},
          std::pair{0xB4, 0x017D}, std::pair{0xB8, 0x017E}, std::pair{0xBC, 0x0152},
          std::pair{0xBD, 0x0153}, std::pair{0xBE, 0x0178}})
      info->map[byte] = code;
  }
  info->data = nullptr;
  info->convert = nullptr;
  info->release = nullptr;
  return XML_STATUS_OK;
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
  XML_SetUnknownEncodingHandler(parser.get(), on_unknown_encoding, nullptr);
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
  for (const NodeRef& ref : scan.refs) {
    if (!scan.nodes.count(ref.node)) {
      throw ParseError(ref.where, "nd ref",
                       "node " + ref.node + " is not in the file: the way is incomplete");
    }
    if (!ref.node_seen) {
      // The driver reads nodes as they come and drops a way's point whose node is still unknown.
      throw ParseError(ref.where, "nd ref",
                       "node " + ref.node +
                           " comes after this way in the file, which GDAL's OSM driver reads in "
                           "order: write the nodes before the ways, as OSM files do");
    }
  }
}

}  // namespace wifislam::floorplan
