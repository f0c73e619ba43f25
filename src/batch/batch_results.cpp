#include "batch/batch_results.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "fastshade/error.h"

namespace fastshade {

namespace {

// Holds flock(2) on the file for one append: other processes (shards sharing the directory)
// wait instead of writing between our bytes.
class FileLock {
 public:
  explicit FileLock(int fd) : fd_(fd) {
    while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
    }
  }
  ~FileLock() { ::flock(fd_, LOCK_UN); }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// True if the file is empty or ends with a newline.
bool ends_with_newline(int fd) {
  const off_t size = ::lseek(fd, 0, SEEK_END);
  if (size <= 0) return true;
  char last = '\n';
  return ::pread(fd, &last, 1, size - 1) == 1 && last == '\n';
}

}  // namespace

ResultsLog::ResultsLog(const std::filesystem::path& path) : path_(path) {
  // Read as well: a torn last line is detected by reading the last byte.
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(path.string(), std::string("cannot open for appending: ") + std::strerror(errno));
}

ResultsLog::~ResultsLog() {
  if (fd_ >= 0) ::close(fd_);
}

void ResultsLog::append(const nlohmann::json& line) {
  // Non-ASCII and invalid UTF-8 in paths or messages are escaped or replaced: a line is ASCII.
  const std::string text = line.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace) + "\n";
  const std::lock_guard<std::mutex> guard(mutex_);
  const FileLock lock(fd_);
  // A torn last line from an earlier crash is ended first, so this one starts a line.
  const bool ok = (ends_with_newline(fd_) || write_all(fd_, "\n")) && write_all(fd_, text);
  if (!ok) throw InputError(path_.string(), std::string("cannot append: ") + std::strerror(errno));
}

std::string completed_key(const std::string& output, const std::string& fingerprint) {
  return output + "\n" + fingerprint;
}

std::set<std::string> completed_images(const std::filesystem::path& path) {
  std::set<std::string> done;
  std::ifstream in(path, std::ios::binary);
  const auto text = [](const nlohmann::json& line, const char* key) -> std::string {
    const auto it = line.find(key);
    return it != line.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  for (std::string line; std::getline(in, line);) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (!j.is_object() || text(j, "status") != "ok") continue;  // a torn line is discarded
    done.insert(completed_key(text(j, "output"), text(j, "fingerprint")));
  }
  return done;
}

}  // namespace fastshade
