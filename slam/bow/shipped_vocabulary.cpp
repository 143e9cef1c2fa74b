#include "slam/bow/shipped_vocabulary.hpp"

#include <map>
#include <mutex>

#include "core/error.hpp"

// The file is assembled into read-only data with .incbin (WIFISLAM_SHIPPED_VOCABULARY is its
// absolute path, set by slam/CMakeLists.txt, which also makes this object depend on the file).
// A generated C array would do the same with a 2.7 MB source file to compile.
asm(".section .rodata\n"
    ".balign 16\n"
    ".global wifislam_shipped_vocabulary_begin\n"
    "wifislam_shipped_vocabulary_begin:\n"
    ".incbin \"" WIFISLAM_SHIPPED_VOCABULARY
    "\"\n"
    ".global wifislam_shipped_vocabulary_end\n"
    "wifislam_shipped_vocabulary_end:\n"
    ".previous\n");

extern "C" const char wifislam_shipped_vocabulary_begin[];
extern "C" const char wifislam_shipped_vocabulary_end[];

namespace wifislam::slam::bow {

std::string_view shipped_vocabulary_bytes() {
  return {wifislam_shipped_vocabulary_begin,
          static_cast<std::size_t>(wifislam_shipped_vocabulary_end -
                                   wifislam_shipped_vocabulary_begin)};
}

std::shared_ptr<const VocabularyTree> load_vocabulary(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const VocabularyTree>> loaded;
  std::lock_guard lock(mutex);
  auto& slot = loaded[path];
  if (!slot) {
    slot = std::make_shared<const VocabularyTree>(
        path.empty()
            ? VocabularyTree::deserialise(shipped_vocabulary_bytes(), kShippedVocabularyName)
            : VocabularyTree::load(path));
  }
  return slot;
}

std::string vocabulary_checksum(const std::string& path) {
  // The trailer is the SHA-256 of everything before it; load_vocabulary checked it.
  const std::shared_ptr<const VocabularyTree> vocabulary = load_vocabulary(path);
  const std::string bytes = vocabulary->serialise();
  return bytes.substr(bytes.size() - 64);
}

}  // namespace wifislam::slam::bow
