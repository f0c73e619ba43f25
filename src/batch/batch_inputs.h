// What fastshade batch renders: mesh files found in the inputs, in a fixed order, split into
// shards, each with an output name of its own.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "fastshade/batch.h"

namespace fastshade {

// Expands the inputs: a directory gives every file below it (recursively, symbolic links to
// files included, to directories not followed) whose extension is a mesh format's (obj, off,
// ply, stl, any case); a .txt, .lst or .list file gives the paths on its lines (blank lines
// and lines starting with '#' skipped; relative paths are relative to the list file; a line
// may name a directory); any other argument is a mesh file, which need not exist (its load
// fails, and the batch reports it). Sorted by key, each file once (duplicates found through
// their canonical paths). Throws InputError for an unreadable list file or directory, an
// argument that is none of these, no mesh at all, or two keys whose names collide.
std::vector<BatchMesh> find_meshes(const std::vector<std::string>& inputs);

// Throws parse_shard's InputError, naming `where`, unless 0 <= I < N <= kMaxShards.
void check_shard(Shard shard, const std::string& where);

// The meshes of one shard: the j-th mesh of the sorted list goes to shard j mod N (round
// robin, so that each shard gets a similar mix of directories). The shards partition the list.
std::vector<BatchMesh> take_shard(const std::vector<BatchMesh>& meshes, Shard shard);

// 16 lower-case hex digits of the 64-bit FNV-1a hash: the same on every machine and build
// (std::hash is not), so that names and fingerprints agree across a cluster.
std::string stable_hash(std::string_view text);

}  // namespace fastshade
