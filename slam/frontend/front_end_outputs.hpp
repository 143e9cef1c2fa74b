#pragma once
// A front end's own part of a run folder: extra files (rtabmap_memory.csv, orbslam_queries.csv)
// and its part of run.json's "frontend_summary". Defaults: no file, an empty object.

#include <filesystem>

#include <nlohmann/json_fwd.hpp>

namespace wifislam::slam::frontend {

class FrontEndOutputs {
 public:
  virtual ~FrontEndOutputs() = default;

 protected:
  virtual void write_own_outputs(const std::filesystem::path& /*run_dir*/) const {}
  virtual nlohmann::json own_summary() const;
};

}  // namespace wifislam::slam::frontend
