// What a measurement ran on: the build's commit, this machine's CPU and load, and when.
#pragma once
#include <string>

namespace fastshade {

// The git commit the binary was built from ("<sha>-dirty" with uncommitted edits to tracked
// files, "unknown" outside a git checkout); written into a header at build time by CMake.
std::string build_commit();

// The CPU's model name from /proc/cpuinfo ("unknown" where there is none).
std::string cpu_model();

// The 1-minute load average from /proc/loadavg (-1 where there is none): on a shared machine,
// how many other runnable threads competed with a measurement.
double load_average();

// Now, as "2026-11-22T14:03:00Z".
std::string utc_now();

}  // namespace fastshade
