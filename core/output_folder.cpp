#include "core/output_folder.hpp"

#include <pwd.h>
#include <unistd.h>

#include <cstdlib>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "core/dataset_format.hpp"
#include "core/error.hpp"

namespace wifislam {

namespace fs = std::filesystem;

namespace {

/// True when `inner` is `outer` or lies inside it (both resolved).
bool is_within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

[[noreturn]] void refuse(const fs::path& path, const std::string& reason) {
  throw InvalidInputError(fmt::format("output folder {}: {}", path.string(), reason));
}

bool is_empty_folder(const fs::path& folder) {
  std::error_code ec;
  return fs::is_empty(folder, ec) && !ec;
}

bool is_regular(const fs::path& file) {
  std::error_code ec;
  return fs::is_regular_file(file, ec);
}

}  // namespace

fs::path resolve_path(const fs::path& path) {
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) resolved = fs::absolute(path, ec).lexically_normal();
  while (!resolved.has_filename() && resolved.has_relative_path()) {
    resolved = resolved.parent_path();  // "dir/" -> "dir"
  }
  return resolved;
}

fs::path absolute_folder(const fs::path& folder) {
  fs::path normal = fs::absolute(folder).lexically_normal();
  while (!normal.has_filename() && normal.has_relative_path()) normal = normal.parent_path();
  return normal;
}

bool has_output_marker(const fs::path& folder) { return is_regular(folder / kOutputMarkerFile); }
bool has_unfinished_marker(const fs::path& folder) {
  return is_regular(folder / kUnfinishedMarkerFile);
}

namespace {

/// The user's home folder as $HOME says and as the password database says: a shell with HOME
/// unset or pointed elsewhere must not make the real home replaceable.
std::vector<fs::path> home_folders() {
  std::vector<fs::path> homes;
  if (const char* home_env = std::getenv("HOME"); home_env && *home_env) {
    homes.push_back(resolve_path(home_env));
  }
  std::vector<char> buffer(16384);
  passwd entry{};
  passwd* found = nullptr;
  if (::getpwuid_r(::getuid(), &entry, buffer.data(), buffer.size(), &found) == 0 && found &&
      found->pw_dir && *found->pw_dir) {
    homes.push_back(resolve_path(found->pw_dir));
  }
  return homes;
}

}  // namespace

void check_folder_replaceable(const fs::path& resolved) {
  if (resolved == resolved.root_path()) refuse(resolved, "refusing to replace the root folder");
  std::error_code ec;
  const fs::path cwd = resolve_path(fs::current_path(ec));
  if (!ec && is_within(cwd, resolved)) {
    refuse(resolved, cwd == resolved ? "is the current directory; refusing to replace it"
                                     : "holds the current directory (" + cwd.string() +
                                           "); refusing to replace it");
  }
  for (const fs::path& home : home_folders()) {
    if (is_within(home, resolved)) {
      refuse(resolved, home == resolved ? "is the home folder; refusing to replace it"
                                        : "holds the home folder (" + home.string() +
                                              "); refusing to replace it");
    }
  }
  if (has_unfinished_marker(resolved)) {
    // Another run's staging folder: replacing it pulled the folder from under that run, which
    // then failed with "write failed (disk full?)" and never put its output in place.
    refuse(resolved, fmt::format("is a folder another wifislam run is writing now, or left "
                                 "unfinished ({} is in it); refusing to replace it. Choose "
                                 "another folder, or remove this one once no run writes it",
                                 kUnfinishedMarkerFile));
  }
  if (!is_empty_folder(resolved) && !has_output_marker(resolved)) {
    refuse(resolved,
           fmt::format("does not look like wifislam output (no {} marker) and is not empty; "
                       "refusing to replace it, even with --force. Choose another folder or "
                       "remove this one yourself",
                       kOutputMarkerFile));
  }
}

fs::path staging_path_of(const fs::path& final_path) { return final_path.string() + ".partial"; }
fs::path set_aside_path_of(const fs::path& final_path) { return final_path.string() + ".replaced"; }

namespace {

/// Missing, or a folder that is empty or holds `marker`.
bool missing_or_marked(const fs::path& folder, const char* marker) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(folder, ec);
  if (!fs::exists(status)) return true;
  return fs::is_directory(status) && (is_empty_folder(folder) || is_regular(folder / marker));
}

}  // namespace

void check_set_aside_free(const fs::path& resolved_final) {
  const fs::path set_aside = set_aside_path_of(resolved_final);
  if (!missing_or_marked(set_aside, kDiscardedMarkerFile)) {
    throw InvalidInputError(fmt::format(
        "{}: exists, and replacing {} sets the old folder aside there first; move it away (it "
        "may be an earlier output whose replacement was interrupted)",
        set_aside.string(), resolved_final.string()));
  }
}

void check_folders_beside(const fs::path& resolved_final) {
  const fs::path staging = staging_path_of(resolved_final);
  std::error_code ec;
  // Both may be removed (a leftover, a replaced folder): never while they hold the current
  // directory or the home folder (a shell left inside a leftover `ds.partial`).
  std::vector<fs::path> kept = home_folders();
  if (const fs::path cwd = fs::current_path(ec); !ec) kept.push_back(resolve_path(cwd));
  for (const fs::path& beside : {staging, set_aside_path_of(resolved_final)}) {
    for (const fs::path& folder : kept) {
      if (is_within(folder, beside)) {
        throw InvalidInputError(fmt::format(
            "{}: holds {}, and this run may remove it (it writes {} first and sets a folder it "
            "replaces aside as {}); run it from elsewhere",
            beside.string(), folder.string(), staging.string(),
            set_aside_path_of(resolved_final).string()));
      }
    }
  }
  if (!missing_or_marked(staging, kUnfinishedMarkerFile)) {
    // Finished but not in place: a run killed between its last two steps (or a power cut) left
    // the new output here and, when it was replacing one, the old one at <final>.replaced.
    const bool interrupted_commit =
        has_output_marker(staging) &&
        (!fs::exists(resolved_final, ec) || fs::exists(set_aside_path_of(resolved_final), ec));
    throw InvalidInputError(
        interrupted_commit
            ? fmt::format("{}: exists and holds a finished output: one named so, or one never "
                          "moved into place (its run stopped at its very end); rename it to {} "
                          "if it is the one you want{}, or move it away",
                          staging.string(), resolved_final.string(),
                          fs::exists(set_aside_path_of(resolved_final), ec)
                              ? " (the folder it replaced is " +
                                    set_aside_path_of(resolved_final).string() + ")"
                              : "")
            : fmt::format("{}: exists, and this run writes its output there first; it is no "
                          "unfinished output of a run (no {}): a finished output named so, a "
                          "folder of yours, or one an older wifislam left. Move it away or "
                          "remove it",
                          staging.string(), kUnfinishedMarkerFile));
  }
  if (fs::exists(resolved_final, ec)) check_set_aside_free(resolved_final);
}

std::string remove_folder_marker_last(const fs::path& folder, const char* marker) {
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(folder, ec))) {
    // A link (an external system can put one where the run's folder was): the link goes, never
    // what it names, as remove_all would have it.
    fs::remove(folder, ec);
    return ec ? folder.string() + ": " + ec.message() : std::string();
  }
  // Everything but the marker; an entry that could not be listed or removed keeps the marker.
  std::string failure;
  const auto others = [&] {
    std::vector<fs::path> entries;
    fs::directory_iterator it(folder, ec), end;
    for (; !ec && it != end; it.increment(ec))
      if (it->path().filename() != marker) entries.push_back(it->path());
    if (ec && failure.empty()) failure = folder.string() + ": " + ec.message();
    return entries;
  };
  for (const fs::path& entry : others()) {
    fs::remove_all(entry, ec);
    if (ec && failure.empty()) failure = entry.string() + ": " + ec.message();
  }
  if (!failure.empty()) return failure;
  if (const std::vector<fs::path> left = others(); !left.empty() || !failure.empty())
    return failure.empty() ? left.front().string() + ": still there" : failure;
  fs::remove(folder / marker, ec);
  if (!ec) fs::remove(folder, ec);
  return ec ? folder.string() + ": " + ec.message() : std::string();
}

fs::path link_named_by(const fs::path& path) {
  fs::path named = path;
  while (named.has_relative_path() && (!named.has_filename() || named.filename() == "."))
    named = named.parent_path();
  std::error_code ec;
  return fs::is_symlink(fs::symlink_status(named, ec)) ? named : fs::path();
}

bool check_output_folder(const OutputFolderRequest& request) {
  if (request.path.empty()) throw InvalidInputError("output folder: the path is empty");
  std::error_code ec;
  // Replacing a symbolic link's path replaces the folder it points to, wherever that is: a link
  // at eval's default <run>/eval to a dataset emptied the dataset without --force. The folder
  // itself must be named.
  if (const fs::path link = link_named_by(request.path); !link.empty()) {
    const fs::path target = fs::read_symlink(link, ec);
    refuse(link, "is a symbolic link (to " + target.string() +
                     "); refusing to write through it: give the folder itself, or remove the "
                     "link");
  }
  const fs::path out = resolve_path(request.path);
  const fs::file_status status = fs::status(out, ec);
  const bool is_default =
      !request.owned_default.empty() && resolve_path(request.owned_default) == out;
  // Checked before existence: a new folder inside an input changes the input by being there
  // (a run folder inside a dataset, export's links inside the dataset they link to).
  const fs::path container =
      request.default_container.empty() ? fs::path() : resolve_path(request.default_container);
  for (const fs::path& input : request.inputs) {
    if (input.empty()) continue;
    const fs::path in = resolve_path(input);
    if (in == out) refuse(out, "is an input of this command (" + input.string() + ")");
    // A leftover <out>.partial (read with --no-verify) or a <out>.replaced given as the input:
    // this run would remove it.
    for (const fs::path& beside : {staging_path_of(out), set_aside_path_of(out)}) {
      if (request.staged_beside && is_within(in, beside)) {
        refuse(out, "this run writes or sets aside " + beside.string() +
                        ", which is or holds an input of this command (" + input.string() + ")");
      }
    }
    if (!(is_default && in == container) && is_within(out, in)) {
      refuse(out, "lies inside an input of this command (" + input.string() +
                      "); write it next to it instead");
    }
  }
  if (!fs::exists(status)) {
    if (request.staged_beside) check_folders_beside(out);
    return false;
  }
  if (!fs::is_directory(status)) {
    refuse(out, "exists and is not a folder; refusing to replace it");
  }
  for (const fs::path& input : request.inputs) {
    if (!input.empty() && is_within(resolve_path(input), out)) {
      refuse(out, "holds an input of this command (" + input.string() + ")");
    }
  }
  check_folder_replaceable(out);
  if (!request.force && !is_default) refuse(out, "already exists (pass --force to replace it)");
  if (request.staged_beside) check_folders_beside(out);
  return true;
}

void check_output_file(const fs::path& path, const std::vector<fs::path>& inputs) {
  if (path.empty()) throw InvalidInputError("output file: the path is empty");
  const fs::path out = resolve_path(path);
  std::error_code ec;
  if (fs::is_directory(out, ec)) {
    throw InvalidInputError("output file " + path.string() +
                            ": is a folder; give a file name to write");
  }
  for (const fs::path& input : inputs) {
    if (input.empty()) continue;
    const fs::path in = resolve_path(input);
    if (in == out) {
      throw InvalidInputError("output file " + path.string() +
                              ": is an input of this command; refusing to overwrite it");
    }
    // A file inside an input dataset would change that dataset: its manifest then no longer
    // matches, or a file it lists is gone. (Other input folders, an IMDF venue say, may take a
    // file beside what is read.)
    const bool dataset =
        fs::exists(in / dataset::kManifest, ec) || fs::exists(in / dataset::kRgbList, ec);
    if (fs::is_directory(in, ec) && dataset && is_within(out, in)) {
      throw InvalidInputError("output file " + path.string() +
                              ": lies inside an input of this command (" + input.string() +
                              ", a dataset); write it elsewhere");
    }
  }
  check_file_replaceable(out);
  const fs::file_status folder = fs::status(out.parent_path(), ec);
  if (!fs::exists(folder)) {
    throw IoError("output file " + path.string() + ": its folder " + out.parent_path().string() +
                  " does not exist");
  }
  if (!fs::is_directory(folder)) {
    throw InvalidInputError("output file " + path.string() + ": " + out.parent_path().string() +
                            " is not a folder");
  }
}

void check_output_files(const std::vector<fs::path>& outputs, const std::vector<fs::path>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].empty()) continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (!outputs[j].empty() && resolve_path(outputs[j]) == resolve_path(outputs[i])) {
        throw InvalidInputError("output file " + outputs[i].string() + ": is also given as " +
                                outputs[j].string() + "; each output needs a file of its own");
      }
    }
  }
  for (const fs::path& output : outputs) {
    if (!output.empty()) check_output_file(output, inputs);
  }
}

void check_file_replaceable(const fs::path& path) {
  std::error_code ec;
  const fs::file_status target = fs::status(path, ec);
  if (fs::exists(target) && !fs::is_regular_file(target)) {
    throw InvalidInputError(path.string() + ": exists and is not a regular file (" +
                            (fs::is_directory(target) ? "a folder" : "a device, pipe or socket") +
                            "); give the path of a file to write");
  }
  // The file is written as <path>.partial first, which truncates a file of that name. Inside a
  // folder of ours (one holding the output marker, or below one) that is a write of ours that was
  // interrupted (a resumed `paper` folder); anywhere else it may be the user's file.
  const fs::path partial = path.string() + ".partial";
  const fs::file_status existing = fs::symlink_status(partial, ec);
  if (!fs::exists(existing)) return;
  bool ours = false;
  for (fs::path folder = resolve_path(fs::absolute(path, ec).parent_path());
       !ours && folder.has_relative_path(); folder = folder.parent_path())
    ours = has_output_marker(folder);
  if (!fs::is_regular_file(existing) || !ours) {
    throw InvalidInputError(partial.string() + ": exists, and " + path.string() +
                            " is written there first; move it away (it may be left by an "
                            "interrupted write)");
  }
}

}  // namespace wifislam
