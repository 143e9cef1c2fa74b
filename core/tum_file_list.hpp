#pragma once
// TUM RGB-D file lists: rgb.txt / depth.txt ("timestamp filename" per line) and
// associations.txt ("t_rgb rgb_file t_depth depth_file", as written by TUM's associate.py), plus
// the association rule itself and a streaming reader of TUM trajectory lines (groundtruth.txt,
// odometry.txt) that does not hold the whole file in memory.

#include <optional>
#include <string>
#include <vector>

#include "core/line_cursor.hpp"
#include "core/timestamp.hpp"
#include "core/tum_trajectory.hpp"

namespace wifislam {

struct TumFileEntry {
  Timestamp time;
  std::string path;  // as written in the list, relative to the dataset folder
  int line = 0;
};

/// An rgb image and the depth image associated with it.
struct FramePair {
  Timestamp rgb_time;
  std::string rgb_path;
  Timestamp depth_time;
  std::string depth_path;
  int line = 0;      // line in associations.txt (0 when associated in memory)
  int rgb_line = 0;  // line in rgb.txt when associated in memory (0 otherwise)
};

/// Streams "timestamp filename" lines. ParseError("file:line") for a line without exactly two
/// fields, a bad timestamp, or a timestamp not later than the previous one.
class TumFileListReader {
 public:
  explicit TumFileListReader(const std::string& path) : cursor_(path) {}
  std::optional<TumFileEntry> next();

 private:
  LineCursor cursor_;
  std::optional<Timestamp> last_;
};
std::vector<TumFileEntry> read_tum_file_list(const std::string& path);

/// Streams associations.txt lines (4 fields), checking that rgb times increase.
class AssociationsReader {
 public:
  explicit AssociationsReader(const std::string& path) : cursor_(path) {}
  std::optional<FramePair> next();
  const std::string& path() const { return cursor_.path(); }

 private:
  LineCursor cursor_;
  std::optional<Timestamp> last_;
};

/// TUM associate.py: every (rgb, depth) pair closer than `max_difference_s` is a candidate;
/// candidates are taken greedily from the closest, each stamp used at most once; the result is
/// sorted by rgb time.
std::vector<FramePair> associate_tum(const std::vector<TumFileEntry>& rgb,
                                     const std::vector<TumFileEntry>& depth,
                                     double max_difference_s);

std::string format_tum_file_line(Timestamp time, const std::string& path);
std::string format_association_line(const FramePair& pair);

/// Streams a TUM trajectory file (same checks and messages as read_tum_trajectory).
class TumTrajectoryReader {
 public:
  explicit TumTrajectoryReader(const std::string& path) : cursor_(path) {}
  std::optional<StampedPose> next();

 private:
  LineCursor cursor_;
  std::optional<Timestamp> last_;
};

}  // namespace wifislam
