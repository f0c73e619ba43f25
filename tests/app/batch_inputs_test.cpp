// What fastshade batch finds in its inputs, how it splits them into shards, and the small pieces
// of its run: signals, progress durations.
#include "batch/batch_inputs.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "app/batch_progress.h"
#include "app/stop_signals.h"
#include "fastshade/error.h"
#include "io/io_test_util.h"

namespace fastshade {
namespace {

namespace fs = std::filesystem;
using testing::ScratchDir;

std::vector<std::string> keys_of(const std::vector<BatchMesh>& meshes) {
  std::vector<std::string> keys;
  for (const BatchMesh& m : meshes) keys.push_back(m.key);
  return keys;
}

std::string error_of(const std::vector<std::string>& inputs) {
  try {
    find_meshes(inputs);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(BatchInputs, DirectoriesAndListFilesGiveSortedMeshesOnceWithDistinctNames) {
  const ScratchDir scratch;
  const fs::path d = scratch.path();
  for (const char* name : {"m/b/x.ply", "m/a/x.ply", "m/a/y.OBJ", "m/c/deep/z.stl", "m/notes.md"}) {
    fs::create_directories((d / name).parent_path());
    scratch.write(name, "not read here");
  }
  // A list file: a comment, a blank line, a path relative to the list, one outside, a directory,
  // and a mesh the directory argument finds too (rendered once).
  scratch.write("m/list.txt", "# meshes\n\n  a/x.ply  \r\n../elsewhere/w.off\nc\n");
  const std::vector<BatchMesh> meshes =
      find_meshes({(d / "m").string(), (d / "m/list.txt").string(), (d / "m/a/y.OBJ").string()});
  const std::string m = (d / "m").string();
  EXPECT_EQ(keys_of(meshes), (std::vector<std::string>{(d / "elsewhere/w.off").string(),
                                                        m + "/a/x.ply", m + "/a/y.OBJ",
                                                        m + "/b/x.ply", m + "/c/deep/z.stl"}));
  std::set<std::string> names;
  for (const BatchMesh& mesh : meshes) {
    names.insert(mesh.name);
    EXPECT_EQ(mesh.name.size(), mesh.path.stem().string().size() + 17) << mesh.name;
    EXPECT_EQ(mesh.name.rfind(mesh.path.stem().string() + "-", 0), 0u) << mesh.name;
  }
  EXPECT_EQ(names.size(), meshes.size());  // a/x.ply and b/x.ply do not collide
  EXPECT_EQ(meshes[0].file_bytes, 0u);    // w.off does not exist: its load will fail
  EXPECT_GT(meshes[1].file_bytes, 0u);
}

TEST(BatchInputs, UnusableInputsAreUsageErrors) {
  const ScratchDir scratch;
  const fs::path d = scratch.path();
  fs::create_directories(d / "empty");
  scratch.write("readme.md", "text");
  scratch.write("binary.lst", std::string("a\0b", 3));
  EXPECT_NE(error_of({(d / "empty").string()}).find("no mesh files"), std::string::npos);
  EXPECT_NE(error_of({(d / "readme.md").string()}).find("not a mesh file"), std::string::npos);
  EXPECT_NE(error_of({(d / "missing.txt").string()}).find("no such list file"), std::string::npos);
  EXPECT_NE(error_of({(d / "nothing").string()}).find("no such file"), std::string::npos);
  EXPECT_NE(error_of({(d / "binary.lst").string()}).find("NUL"), std::string::npos);
}

TEST(BatchInputs, ShardsPartitionTheMeshes) {
  std::vector<BatchMesh> all(23);
  for (std::size_t i = 0; i < all.size(); ++i) all[i].key = "mesh" + std::to_string(100 + i);
  const std::vector<std::string> keys = keys_of(all);
  const std::multiset<std::string> each_once(keys.begin(), keys.end());
  for (int count = 1; count <= 30; ++count) {
    std::multiset<std::string> seen;
    for (int index = 0; index < count; ++index) {
      const std::string shard = std::to_string(index) + "/" + std::to_string(count);
      const std::vector<BatchMesh> part = take_shard(all, parse_shard(shard));
      EXPECT_LE(part.size(), (all.size() + count - 1) / count);  // balanced within one mesh
      for (const BatchMesh& m : part) seen.insert(m.key);
    }
    EXPECT_EQ(seen, each_once) << count << " shards";
  }
}

TEST(BatchInputs, ShardSyntaxIsChecked) {
  EXPECT_EQ(parse_shard("2/5").index, 2);
  EXPECT_EQ(parse_shard("2/5").count, 5);
  for (const char* bad :
       {"", "1", "5/5", "-1/3", "0/0", "a/b", "1/2x", " 1/2", "1/", "/2", "0/1000001"})
    EXPECT_THROW(parse_shard(bad), InputError) << "'" << bad << "'";
}

TEST(BatchInputs, StableHashIsFnv1a64) {
  // Published FNV-1a 64 test vectors: names must not change between builds or machines.
  EXPECT_EQ(stable_hash(""), "cbf29ce484222325");
  EXPECT_EQ(stable_hash("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(stable_hash("foobar"), "85944171f73967e8");
}

TEST(StopSignals, FirstSignalOnlySetsTheFlag) {
  {
    const StopSignals signals;
    EXPECT_EQ(StopSignals::received(), 0);
    ::raise(SIGINT);  // would end the test program without the handler
    EXPECT_EQ(StopSignals::received(), SIGINT);
  }
  struct sigaction now = {};
  ::sigaction(SIGINT, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);  // restored
}

TEST(BatchProgress, DurationsReadLikeAClock) {
  EXPECT_EQ(format_clock(0), "0:00");
  EXPECT_EQ(format_clock(59.4), "0:59");
  EXPECT_EQ(format_clock(61), "1:01");
  EXPECT_EQ(format_clock(3725), "1:02:05");
}

}  // namespace
}  // namespace fastshade
