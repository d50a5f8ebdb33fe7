#ifndef EDYN_ECS_SIGH_HPP
#define EDYN_ECS_SIGH_HPP

#include "edyn/ecs/delegate.hpp"
#include <algorithm>
#include <cstddef>
#include <vector>

namespace edyn {

/// A signal; only the specialisation for function types, `sigh<Ret(Args...)>`, is defined.
template<typename>
class sigh;

/// The listening side of a signal; only `sink<sigh<Ret(Args...)>>` is defined.
template<typename>
class sink;

/// A signal: a list of delegates called in the order they were connected.
///
/// Listeners are added and removed through a `sink` (`edyn::sink{signal}.connect<&fn>()`), so
/// that code that may listen cannot also publish. The registry's `on_construct`, `on_update` and
/// `on_destroy` give sinks of such signals.
///
/// Changes made by listeners while `publish` runs (the signal is "publishing"):
/// - a listener disconnected during a publish (itself or another) is not called again by it,
///   even if it had not been reached yet;
/// - a listener connected during a publish is first called by the next publish;
/// - a listener may publish the same signal again (nested publish); the rules above apply to
///   each level.
///
/// Destroying the signal while it publishes is undefined behaviour. A signal is not thread-safe.
/// @tparam Ret Return type of the listeners (their results are discarded).
/// @tparam Args Argument types of the listeners.
template<typename Ret, typename... Args>
class sigh<Ret(Args...)> {
    friend class sink<sigh<Ret(Args...)>>;

public:
    /// Unsigned integer type for counts of listeners.
    using size_type = std::size_t;
    /// The delegate type that holds each listener.
    using delegate_type = delegate<Ret(Args...)>;

    /// Number of connected listeners.
    /// @return Listeners connected now, those disconnected during a running publish excluded.
    [[nodiscard]] size_type size() const noexcept { return live; }
    /// Whether no listener is connected.
    /// @return True when `size() == 0`.
    [[nodiscard]] bool empty() const noexcept { return live == 0; }

    /// Calls every listener with `args`, in the order they were connected; return values, if any,
    /// are discarded. An exception thrown by a listener propagates and skips the remaining ones.
    /// @param args Arguments passed to every listener (copied for each call where taken by value).
    void publish(Args... args) {
        // Listeners connected during this call are appended after `count` and wait for the next.
        const auto count = calls.size();
        const publish_guard guard{*this};
        for (size_type i = 0; i < count; ++i) {
            // A copy: a listener that connects may reallocate `calls`.
            const auto call = calls[i];
            if (call) {
                call(args...);
            }
        }
    }

private:
    struct publish_guard {
        explicit publish_guard(sigh &signal) noexcept
            : signal(signal) {
            ++signal.depth;
        }
        publish_guard(const publish_guard &) = delete;
        publish_guard &operator=(const publish_guard &) = delete;
        ~publish_guard() {
            if (--signal.depth == 0 && signal.dirty) {
                signal.compact();
            }
        }
        sigh &signal;
    };

    void add(const delegate_type &call) {
        if (std::find(calls.begin(), calls.end(), call) == calls.end()) {
            calls.push_back(call);
            ++live;
        }
    }

    // While publishing, disconnected slots are reset rather than erased so that the indices the
    // running publish walks stay valid; they are erased once the outermost publish returns.
    template<typename Predicate>
    void remove_if(Predicate predicate) {
        for (auto &call : calls) {
            if (call && predicate(call)) {
                call.reset();
                --live;
                dirty = true;
            }
        }
        if (depth == 0 && dirty) {
            compact();
        }
    }

    void compact() {
        std::erase_if(calls, [](const delegate_type &call) { return !call; });
        dirty = false;
    }

    std::vector<delegate_type> calls;
    size_type live{0};
    unsigned depth{0};
    bool dirty{false};
};

} // namespace edyn

#endif // EDYN_ECS_SIGH_HPP
