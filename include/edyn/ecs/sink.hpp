#ifndef EDYN_ECS_SINK_HPP
#define EDYN_ECS_SINK_HPP

#include "edyn/ecs/delegate.hpp"
#include "edyn/ecs/sigh.hpp"
#include <utility>

namespace edyn {

/// The listening side of a `sigh`: connects and disconnects listeners, cannot publish.
///
/// A sink only points to its signal; it is cheap to copy and must not outlive the signal.
///
/// @code
/// sink{signal}.connect<&free_fn>();        // free_fn(args...)
/// sink{signal}.connect<&cls::member>(obj); // obj.member(args...), obj by reference or pointer
/// sink{signal}.connect<&fn>(payload);      // fn(payload, args...)
/// @endcode
///
/// Connecting a (function, instance) pair that is already connected does nothing: each pair is
/// called at most once per publish. See `sigh` for changes made while the signal publishes.
/// @tparam Ret Return type of the listeners.
/// @tparam Args Argument types of the listeners.
template<typename Ret, typename... Args>
class sink<sigh<Ret(Args...)>> {
    using signal_type = sigh<Ret(Args...)>;
    using delegate_type = delegate<Ret(Args...)>;

public:
    /// A sink of `signal`, which must outlive it.
    /// @param signal The signal whose listeners this sink manages.
    sink(signal_type &signal) noexcept
        : signal(&signal) {}

    /// Whether the signal has no listener.
    /// @return True when no listener is connected.
    [[nodiscard]] bool empty() const noexcept { return signal->empty(); }

    /// Connects `Candidate`, optionally bound to an instance or payload, unless that pair is
    /// already connected. Connected during a publish, it is first called by the next one.
    /// @tparam Candidate Pointer to the free function or member function to call.
    /// @param value_or_instance Nothing, or one object (member function) or payload (free
    /// function), by reference or pointer; the caller keeps it alive while connected.
    template<auto Candidate, typename... Type>
    void connect(Type &&...value_or_instance) {
        static_assert(sizeof...(Type) <= 1, "sink::connect: at most one instance or payload");
        delegate_type call;
        call.template connect<Candidate>(std::forward<Type>(value_or_instance)...);
        signal->add(call);
    }

    /// Disconnects `Candidate` bound to the same instance or payload (or to none); does nothing
    /// if that pair is not connected.
    /// @tparam Candidate Pointer to the free function or member function given to `connect`.
    /// @param value_or_instance The same instance or payload as given to `connect`, if any.
    template<auto Candidate, typename... Type>
    void disconnect(Type &&...value_or_instance) {
        static_assert(sizeof...(Type) <= 1, "sink::disconnect: at most one instance or payload");
        delegate_type target;
        target.template connect<Candidate>(std::forward<Type>(value_or_instance)...);
        signal->remove_if([&target](const delegate_type &call) { return call == target; });
    }

    /// Disconnects every listener bound to this instance or payload, whatever its function.
    /// @param value_or_instance The instance or payload given to `connect`.
    template<typename Type>
    void disconnect(Type &value_or_instance) {
        disconnect_data(&value_or_instance);
    }

    /// Disconnects every listener bound to this instance or payload, given by pointer; does
    /// nothing for a null pointer.
    /// @param value_or_instance The instance or payload given to `connect`.
    template<typename Type>
    void disconnect(Type *value_or_instance) {
        disconnect_data(value_or_instance);
    }

    /// Disconnects every listener.
    void disconnect() {
        signal->remove_if([](const delegate_type &) { return true; });
    }

private:
    void disconnect_data(const void *data) {
        if (data != nullptr) {
            signal->remove_if([data](const delegate_type &call) { return call.data() == data; });
        }
    }

    signal_type *signal;
};

/// Deduces the sink type from its signal: `edyn::sink{signal}`.
template<typename Ret, typename... Args>
sink(sigh<Ret(Args...)> &) -> sink<sigh<Ret(Args...)>>;

} // namespace edyn

#endif // EDYN_ECS_SINK_HPP
