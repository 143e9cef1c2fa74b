#pragma once
// Writes a generated dataset folder (core/dataset_format.hpp).
//
// Atomic: everything goes into `<output>.partial/`, renamed to `<output>` only when complete; an
// error removes the partial folder, so nothing that looks finished is left behind.
// Streaming: frames are written as they are rendered; memory stays flat with the length.
// Parallel and deterministic: the main thread renders in time order while worker threads encode
// and write PNGs; list files are written in frame order by the main thread, so every byte is the
// same whatever the thread count.

#include <filesystem>
#include <memory>

#include "sim/generate/generate_options.hpp"
#include "sim/scene/scene.hpp"
#include "sim/site/site.hpp"

namespace wifislam::sim::generate {

/// Generates the dataset of `scene` (with the options' overrides) into `output`. Throws
/// InvalidInputError when `output` exists and `options.overwrite` is false, or when it may not be
/// replaced at all (AtomicDirectory, core/output_folder.hpp); IoError on write errors; the
/// scene's and the renderer's errors pass through.
GenerateSummary generate_dataset(const scene::Scene& scene, const std::filesystem::path& output,
                                 const GenerateOptions& options = {});

/// The same on a site built already, which the caller keeps using (its world for plots, its
/// radio for studies). Its scene is the dataset's: the seed and fps overrides belong in the
/// site's scene (resolve_scene), and `options` must not set them (std::invalid_argument).
GenerateSummary generate_dataset(std::shared_ptr<const site::Site> site,
                                 const std::filesystem::path& output,
                                 const GenerateOptions& options = {});

}  // namespace wifislam::sim::generate
