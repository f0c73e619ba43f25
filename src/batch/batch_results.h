// results.jsonl: one JSON object a line, one line per image and run, appended by every run and
// every shard that writes to the directory. Each line goes out in one write(2) on a file opened
// with O_APPEND under an exclusive flock, so lines from threads and processes never interleave
// and an interruption leaves whole lines (at worst a torn last line if the machine dies or the
// disk fills: readers skip lines that do not parse, and the next writer ends it first).
#pragma once
#include <filesystem>
#include <mutex>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

namespace fastshade {

class ResultsLog {
 public:
  // Opens (creating) the file for appending. Throws InputError naming it if it cannot.
  explicit ResultsLog(const std::filesystem::path& path);
  ~ResultsLog();
  ResultsLog(const ResultsLog&) = delete;
  ResultsLog& operator=(const ResultsLog&) = delete;

  // Thread-safe. Throws InputError naming the file if the write fails.
  void append(const nlohmann::json& line);

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::mutex mutex_;
};

// "OUTPUT\nFINGERPRINT" of every line with "status": "ok" in the file (none if it does not
// exist): the images an earlier run wrote completely, and with which settings.
std::set<std::string> completed_images(const std::filesystem::path& path);
std::string completed_key(const std::string& output, const std::string& fingerprint);

}  // namespace fastshade
