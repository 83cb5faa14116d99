// A staircase step as the browser answers it (which of A and B is the reference's copy), over either
// form of Session's staircase interface: the core drawing the comparison's interval and scoring the
// choice (staircase_comparison / staircase_step(interval)), or the view drawing it from the session's
// seed and the core taking the score (staircase_step(correct)).
#pragma once
#include <cstdint>
#include <random>

namespace ms::web {

// Whether the comparison is in interval B in the step about to be answered.
template <class S>
bool staircase_comparison_in_b(S& session) {
  if constexpr (requires { session.staircase_comparison(); }) {
    using Interval = decltype(session.staircase_comparison());
    return session.staircase_comparison() == Interval::b;
  } else {
    const std::size_t step = session.staircase().levels().size();
    std::mt19937_64 rng(session.schedule().seed ^ (0x9e3779b97f4a7c15ULL * (step + 1)));
    return (rng() & 1U) != 0;
  }
}

// Commits the step the listener answered by choosing B (or A); returns whether that was right.
template <class S>
bool take_staircase_step(S& session, bool chose_b, double rt_ms, std::int64_t now_ms) {
  if constexpr (requires { session.staircase_comparison(); }) {
    using Interval = decltype(session.staircase_comparison());
    return session.staircase_step(chose_b ? Interval::b : Interval::a, rt_ms, now_ms);
  } else {
    const bool correct = chose_b != staircase_comparison_in_b(session);  // the reference's copy is the other one
    session.staircase_step(correct, rt_ms, now_ms);
    return correct;
  }
}

}  // namespace ms::web
