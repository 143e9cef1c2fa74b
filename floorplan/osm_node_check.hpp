#pragma once
// What GDAL's OSM driver reads from an .osm file without a word, checked before it reads it:
// - a way that names a node the file does not hold, or one that comes after the way: the driver
//   drops the point and imports a smaller polygon;
// - a node whose lat or lon is not a number (`lat="abc"`, `lat=""`): the driver reads it as 0,
//   and the import failed far from the cause ("walkable space too small").
// The file is read with expat, the XML parser GDAL's OSM driver reads it with, so comments,
// character references, attributes over several lines, files written on one line and the
// encodings GDAL adds to expat's (windows-1252, ISO-8859-15) are read as GDAL reads them; spaces
// around a number are no error (GDAL reads `lat=" 51.5"` as 51.5).

#include <filesystem>

namespace wifislam::floorplan {

/// Throws ParseError naming "file:line (node/ID)" or "file:line (way/ID)" for either case, and
/// "file:line" with expat's reason for a file that is not well-formed XML; IoError when the file
/// cannot be read.
void check_osm_nodes(const std::filesystem::path& file);

}  // namespace wifislam::floorplan
