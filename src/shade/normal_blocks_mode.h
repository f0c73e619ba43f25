// The --normals choice, alone so that plain data structs can hold it (shade/normal_blocks.h).
#pragma once

namespace fastshade {

enum class SpanNormals { Normalize, Adaptive, EqualAngle };

}  // namespace fastshade
