// Writes a file atomically: into a temporary file beside the target, renamed over the target only
// once everything is written and flushed. On any failure (and on SIGINT, SIGTERM, SIGHUP) the
// temporary file is removed, so a reader never sees a partial or stale output file.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hlr::app {

class AtomicFile {
 public:
  // Creates the temporary file next to `path`. Throws UserError(path, "cannot write (...)") when
  // the directory does not exist or is not writable, or when `path` is an existing directory.
  explicit AtomicFile(std::string path);
  ~AtomicFile();  // removes the temporary file unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view data);  // throws UserError
  // Flushes to disk and renames the temporary file into place. Throws UserError.
  void commit();

  const std::string& path() const { return path_; }

 private:
  void fail(int error);  // removes the temporary file, then throws UserError for errno `error`
  void discard() noexcept;

  std::string path_;
  std::string temp_path_;
  int fd_ = -1;
  bool committed_ = false;
};

// Every output of a run: opened together before the work starts, so that a bad path fails fast,
// and committed together at its end, so that a failed run leaves none of them.
class OutputFiles {
 public:
  explicit OutputFiles(const std::vector<std::string>& paths);
  AtomicFile& operator[](std::size_t i) { return *files_[i]; }
  std::size_t size() const { return files_.size(); }
  void commit();

 private:
  std::vector<std::unique_ptr<AtomicFile>> files_;
};

}  // namespace hlr::app
