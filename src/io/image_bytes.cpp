#include <new>

#include "core/limits.h"
#include "fastshade/image.h"

namespace fastshade {

namespace {
constexpr std::align_val_t kCacheLine{limits::kCacheLineBytes};
}  // namespace

void* allocate_cache_lines(std::size_t bytes) { return ::operator new(bytes, kCacheLine); }

void free_cache_lines(void* block) { ::operator delete(block, kCacheLine); }

}  // namespace fastshade
