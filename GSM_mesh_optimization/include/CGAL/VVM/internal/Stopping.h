// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stopping cleanly, for every entry point of the three packages: one
// `maximum_running_time` counted from the call's start and shared by its
// stages, and visitors that may ask to stop by returning `false`, called with the
// reports they can take (VVM::Stage_report and the rounds' reports derived from it).

#ifndef CGAL_VVM_INTERNAL_STOPPING_H
#define CGAL_VVM_INTERNAL_STOPPING_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>
#include <CGAL/VVM/Stage_report.h>

#include <algorithm>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace VVM {
namespace internal {

/// the time limit of one call (`maximum_running_time`, 0: none), started at construction:
/// each stage asks `is_reached()` between its steps and hands `remaining()` to the calls it makes
class Time_limit
{
public:
  explicit Time_limit(double seconds = 0) : limit_(seconds) { timer_.start(); }

  bool is_set() const { return limit_ > 0; }
  double elapsed() const { return timer_.time(); }
  bool is_reached() const { return limit_ > 0 && timer_.time() >= limit_; }
  /// the time left, as a `maximum_running_time` for a nested call: 0 (none) without a limit,
  /// else positive, so that a call given it once the limit is reached stops at once
  double remaining() const { return limit_ > 0 ? (std::max)(limit_ - timer_.time(), 1e-9) : 0.; }

private:
  CGAL::Real_timer timer_;
  double limit_;
};

/// calls `visitor(args...)`; returns `false` if the visitor returns a `bool` and it is `false`
/// (it asks the algorithm to stop), `true` otherwise
template <class Visitor, class... Args>
bool visit(const Visitor& visitor, Args&&... args)
{
  if constexpr(std::is_void<decltype(visitor(std::forward<Args>(args)...))>::value) {
    visitor(std::forward<Args>(args)...);
    return true;
  } else
    return bool(visitor(std::forward<Args>(args)...));
}

/// calls `visitor(report)` if the visitor takes a `Report` (a `Stage_report` or a round's
/// report derived from it); returns `false` if it asks to stop
template <class Visitor, class Report>
bool visit_report(const Visitor& visitor, const Report& report)
{
  if constexpr(std::is_invocable<const Visitor&, const Report&>::value)
    return visit(visitor, report);
  else
    return true;
}

/// the report of `stage`'s end, after `rounds` rounds, `elapsed` seconds into the call
template <class Visitor>
bool visit_stage_end(const Visitor& visitor, Stage stage, int rounds, double elapsed)
{
  Stage_report r;
  r.stage = stage;
  r.round = rounds;
  r.elapsed_time = elapsed;
  r.stage_done = true;
  return visit_report(visitor, r);
}

/// refuses, at compile time, a visitor given that can take none of `Reports` (the reports an
/// entry point gives, the most derived ones): it would never be called
template <class Visitor, class... Reports>
constexpr void check_visitor()
{
  static_assert(std::is_same<Visitor, CGAL::internal_np::Param_not_found>::value ||
                    (std::is_invocable<const Visitor&, const Reports&>::value || ...),
                "VVM: the visitor can take none of this entry point's reports: give a callable, const, "
                "taking a const VVM::Stage_report& (every stage) or a round's report");
}

/// true if a named parameter was given (`get_parameter()` found it)
template <class Parameter>
constexpr bool is_given(const Parameter&)
{
  return !std::is_same<Parameter, CGAL::internal_np::Param_not_found>::value;
}

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_STOPPING_H
