#include "atomic_file.hpp"

#include "errors.hpp"
#include "interrupt.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hlr::app {
namespace {

std::string cannot_write(int error) { return std::string("cannot write (") + std::strerror(error) + ")"; }

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_.empty()) throw UserError("\"\"", "cannot write (empty output path)");
  struct stat st {};
  if (::stat(path_.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) throw UserError(path_, cannot_write(EISDIR));

  std::string dir, base;
  auto slash = path_.find_last_of('/');
  if (slash == std::string::npos) {
    dir = ".";
    base = path_;
  } else {
    dir = slash == 0 ? "/" : path_.substr(0, slash);
    base = path_.substr(slash + 1);
  }
  if (base.empty()) throw UserError(path_, cannot_write(EISDIR));  // "out/" names a directory
  std::string templ = (slash == std::string::npos ? std::string() : path_.substr(0, slash + 1)) + "." + base +
                      ".tmp-XXXXXX";
  std::vector<char> buffer(templ.begin(), templ.end());
  buffer.push_back('\0');

  fd_ = ::mkstemp(buffer.data());
  if (fd_ < 0) throw UserError(path_, cannot_write(errno));
  temp_path_ = buffer.data();
  register_temporary(temp_path_.c_str());

  // mkstemp creates the file 0600; give the output the permissions a plain create would give it.
  mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(fd_, 0666 & ~mask) != 0) fail(errno);
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temp_path_.empty()) {
    unregister_temporary(temp_path_.c_str());
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
  }
}

void AtomicFile::fail(int error) {
  discard();
  throw UserError(path_, cannot_write(error));
}

void AtomicFile::write(std::string_view data) {
  if (fd_ < 0) throw UserError(path_, "cannot write (file is already closed)");
  stop_token().check();  // a stopped run writes no more
  while (!data.empty()) {
    ssize_t n = ::write(fd_, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(errno);
    }
    data.remove_prefix(static_cast<std::size_t>(n));
  }
}

void AtomicFile::commit() {
  if (fd_ < 0) throw UserError(path_, "cannot write (file is already closed)");
  if (::fsync(fd_) != 0 && errno != EINVAL && errno != EROFS) fail(errno);
  int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail(errno);
  if (::rename(temp_path_.c_str(), path_.c_str()) != 0) fail(errno);
  unregister_temporary(temp_path_.c_str());
  temp_path_.clear();
  committed_ = true;
}

OutputFiles::OutputFiles(const std::vector<std::string>& paths) {
  for (const auto& path : paths) files_.push_back(std::make_unique<AtomicFile>(path));
}

void OutputFiles::commit() {
  for (auto& file : files_) file->commit();
}

}  // namespace hlr::app
