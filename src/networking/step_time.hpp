#ifndef EDYN_SRC_NETWORKING_STEP_TIME_HPP
#define EDYN_SRC_NETWORKING_STEP_TIME_HPP

namespace edyn::detail {

// Whether something stamped at `time` (s) is due by the step that simulates `step_time` (s),
// steps `dt` apart. Times that name a step fall on it only give or take rounding (both are sums
// of doubles, on different machines), so a time belongs to the step within half a step of it.
// The server's jitter buffer and the client's extrapolation both place inputs by this rule.
inline bool due_by_step(double time, double step_time, double dt) noexcept {
    return time <= step_time + dt / 2;
}

// The longest playout delay (s) a client takes from its server: its time runs at most this far
// ahead of the server's. The server refuses a client's snapshot stamped further than this from
// its own time either way, and a client refuses forwarded inputs stamped further than this from
// the snapshot that carries them.
inline constexpr double max_playout_delay = 10;

} // namespace edyn::detail

#endif // EDYN_SRC_NETWORKING_STEP_TIME_HPP
