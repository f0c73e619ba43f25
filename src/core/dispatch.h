// FASTSHADE_DISPATCH(target, Fn)(args...): calls Fn's HWY_EXPORT entry for `target`
// (core/simd_target.h), where HWY_DYNAMIC_DISPATCH(Fn) would call the process-wide choice.
// For .cpp files that HWY_EXPORT the function.
#pragma once
#include <hwy/highway.h>

#include "core/simd_target.h"

#if HWY_IDE || ((HWY_TARGETS & (HWY_TARGETS - 1)) == 0)
// One compiled target: no tables, a direct call.
#define FASTSHADE_DISPATCH(target, FUNC_NAME) ((void)(target), HWY_STATIC_DISPATCH(FUNC_NAME))
#else
#define FASTSHADE_DISPATCH(target, FUNC_NAME) (*(HWY_DISPATCH_TABLE(FUNC_NAME)[(target).table_index]))
#endif
