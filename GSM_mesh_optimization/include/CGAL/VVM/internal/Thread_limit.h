// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `number_of_threads` named parameter of every entry point: TBB's
// parallelism capped for the duration of the call.

#ifndef CGAL_VVM_INTERNAL_THREAD_LIMIT_H
#define CGAL_VVM_INTERNAL_THREAD_LIMIT_H

#include <tbb/global_control.h>

#include <cstddef>
#include <memory>

namespace CGAL {
namespace VVM {
namespace internal {

/// at most `threads` TBB threads while the returned object lives; no limit for 0
inline std::unique_ptr<tbb::global_control> thread_limit(int threads)
{
  if(threads <= 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
}

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_THREAD_LIMIT_H
