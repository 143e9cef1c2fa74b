#pragma once
// The one rule every command that writes a folder follows before it replaces anything, so that
// no flag or path ever deletes what the user did not ask to delete (README, "Output folders").
//
// An existing output folder is replaced only when all of these hold:
//   - `--force` was given, or the folder is the command's documented default output that the
//     command owns (eval's <run>/eval, the demo's demo-output);
//   - it is not an input of the same command, does not contain one and does not lie inside one
//     (refused even when it does not exist yet), except the default inside the input that owns it
//     (eval's <run>/eval);
//   - it is not `/`, the current directory or the home folder, and holds none of them;
//   - it holds this tool's marker file (see `has_output_marker`), or is empty. Nothing else makes
//     a folder replaceable: file names that look like ours (metrics.json, manifest.json ...) are
//     no proof, and a user's folder holding them must survive `--force`.
// The output path itself is never a symbolic link (replacing it would replace the folder it
// points to, wherever that is); links above it are resolved, and paths are compared after
// resolving symlinks, `..` and trailing slashes. A refusal is an
// InvalidInputError (exit 2) naming the path and the reason, raised before anything is written.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace wifislam {

/// Written into every folder AtomicDirectory creates, so a later `--force` can tell this tool's
/// output from a folder of the user's.
inline constexpr const char* kOutputMarkerFile = ".wifislam-output";
/// Written into AtomicDirectory's staging folder (`<final>.partial`) beside kOutputMarkerFile and
/// removed just before the folder is renamed into place: a leftover `.partial` folder is one an
/// interrupted run was writing only when it holds this file. A finished output (which a user may
/// have named `x.partial`, or renamed so) never does, and is never taken for a leftover.
inline constexpr const char* kUnfinishedMarkerFile = ".wifislam-unfinished";
/// Written into `<final>.replaced` (the folder --force replaced, set aside) once the new folder is
/// in place, before it is deleted: a `<final>.replaced` holding it is one a deletion that was cut
/// short (a second Ctrl-C, SIGKILL) left, and the next run finishes deleting it.
inline constexpr const char* kDiscardedMarkerFile = ".wifislam-discarded";

/// What a command is about to write, and what it reads.
struct OutputFolderRequest {
  OutputFolderRequest(std::filesystem::path path_, bool force_,
                      std::filesystem::path owned_default_,
                      std::vector<std::filesystem::path> inputs_,
                      std::filesystem::path default_container_ = {})
      : path(std::move(path_)),
        force(force_),
        owned_default(std::move(owned_default_)),
        inputs(std::move(inputs_)),
        default_container(std::move(default_container_)) {}

  /// The output folder as the user gave it.
  std::filesystem::path path;
  /// `--force`: replace an existing folder that passes the safety checks.
  bool force = false;
  /// The command's documented default output (empty: none). That folder may be replaced without
  /// `--force`.
  std::filesystem::path owned_default;
  /// Every file or folder the command reads (scene files, datasets, run folders ...). A folder
  /// inside one is refused even when it does not exist yet: its mere presence would change the
  /// input (a run folder inside the dataset it ran on).
  std::vector<std::filesystem::path> inputs;
  /// The one input the default may lie inside (eval's <run>/eval lies inside <run>); empty: none.
  /// Only that one: eval of a trajectory file inside the ground truth's dataset must not write
  /// its default <file>_eval into that dataset.
  std::filesystem::path default_container;
  /// The folder is written through AtomicDirectory, which stages it in `<out>.partial` and sets
  /// the old one aside as `<out>.replaced`: what lies there is checked too (check_folders_beside).
  /// False for a folder a command writes in place (`paper` continues its own folder), which never
  /// touches those paths.
  bool staged_beside = true;
};

/// Applies the rule above. Returns true when the folder exists and may be replaced, false when
/// it does not exist yet. Throws InvalidInputError otherwise.
bool check_output_folder(const OutputFolderRequest& request);

/// For commands that write single files (plots, maps, rendered views), checked before any work:
/// the file must not be an input of the command, an existing path must be a regular file (see
/// `check_file_replaceable`), and its folder must exist (IoError otherwise: a command that writes
/// two files must not write the first and then find it cannot write the second). Throws
/// InvalidInputError.
void check_output_file(const std::filesystem::path& path,
                       const std::vector<std::filesystem::path>& inputs);

/// check_output_file for each of a command's `outputs` (empty paths, for files not asked for, are
/// skipped), after refusing two outputs that are the same file: the second would overwrite the
/// first. Throws InvalidInputError naming both.
void check_output_files(const std::vector<std::filesystem::path>& outputs,
                        const std::vector<std::filesystem::path>& inputs);

/// A file is written by renaming a finished `<path>.partial` over `path`, which would put a regular
/// file where a folder, device or pipe was (as root, over /dev/null): refuses (InvalidInputError)
/// an existing `path` that is not a regular file or a link to one. Every atomic file write applies
/// it (core/atomic_file.hpp, plot's figures).
void check_file_replaceable(const std::filesystem::path& path);

/// The parts of the rule that need no knowledge of the command: `resolved` (an existing folder,
/// see `resolve_path`) is not `/`, the current directory or the home folder, holds none of them,
/// and holds the marker or is empty. Throws InvalidInputError. AtomicDirectory
/// applies this to every folder it replaces, whoever asked.
void check_folder_replaceable(const std::filesystem::path& resolved);

/// The folders AtomicDirectory uses beside `<final>` (resolved): `<final>.partial`, which it
/// writes, and `<final>.replaced`, where it sets a `<final>` it replaces aside. Refuses
/// (InvalidInputError) either when it holds anything no run of ours left: a `.partial` folder
/// that is not empty and has no kUnfinishedMarkerFile (a finished output named so, a folder of
/// the user's, or one an older wifislam left), or a `.replaced` one that is not empty and has no
/// kDiscardedMarkerFile. check_output_folder calls it, so commands refuse before their work.
void check_folders_beside(const std::filesystem::path& resolved_final);
/// The `<final>.replaced` half of check_folders_beside (commit() checks it again).
void check_set_aside_free(const std::filesystem::path& resolved_final);
std::filesystem::path staging_path_of(const std::filesystem::path& final_path);
std::filesystem::path set_aside_path_of(const std::filesystem::path& final_path);

/// Removes `folder` with everything in it, `marker` (a file in it) last: a removal cut short by a
/// kill leaves the marker in place with whatever is left, so the leftover is still known as ours.
/// A `folder` that is a symbolic link is removed as the link, never followed.
/// Returns "" once the folder is gone, else the first entry that could not be listed or removed
/// and why (the folder then keeps its marker).
std::string remove_folder_marker_last(const std::filesystem::path& folder, const char* marker);

/// The symbolic link `path` names, or an empty path when it names none. "link", "link/", "link/."
/// and "link/./" all name the link: resolved, a trailing slash would go through it, and a folder
/// written or replaced through a link is the link's target, wherever that is.
std::filesystem::path link_named_by(const std::filesystem::path& path);

/// Absolute path with symlinks, `.`, `..` and trailing slashes resolved as far as the path exists.
std::filesystem::path resolve_path(const std::filesystem::path& path);

/// An output folder as a command names it back to the user: absolute, with `.` and `..` taken
/// lexically and no trailing slash ("run/" and "run/." are "<cwd>/run"); symlinks kept as given.
std::filesystem::path absolute_folder(const std::filesystem::path& folder);

/// True when `folder` holds the marker file (a regular file named kOutputMarkerFile) that
/// AtomicDirectory writes into every folder it creates.
bool has_output_marker(const std::filesystem::path& folder);
/// True when `folder` holds kUnfinishedMarkerFile: a staging folder that a run is writing now or
/// that an interrupted run left.
bool has_unfinished_marker(const std::filesystem::path& folder);

}  // namespace wifislam
