#ifndef EDYN_ECS_SINK_HPP
#define EDYN_ECS_SINK_HPP

#include "edyn/ecs/delegate.hpp"
#include "edyn/ecs/sigh.hpp"
#include <utility>

namespace edyn {

// The listening side of a `sigh`: connects and disconnects listeners, cannot publish. A sink
// only points to its signal; it is cheap to copy and must not outlive the signal.
//
//   sink{signal}.connect<&free_fn>();           // free_fn(args...)
//   sink{signal}.connect<&cls::member>(obj);     // obj.member(args...), obj by reference or
//   pointer sink{signal}.connect<&fn>(payload);          // fn(payload, args...)
//
// Connecting a (function, instance) pair that is already connected does nothing: each pair is
// called at most once per publish. See `sigh` for changes made while the signal publishes.
template<typename Ret, typename... Args>
class sink<sigh<Ret(Args...)>> {
    using signal_type = sigh<Ret(Args...)>;
    using delegate_type = delegate<Ret(Args...)>;

public:
    sink(signal_type &signal) noexcept
        : signal(&signal) {}

    [[nodiscard]] bool empty() const noexcept { return signal->empty(); }

    template<auto Candidate, typename... Type>
    void connect(Type &&...value_or_instance) {
        static_assert(sizeof...(Type) <= 1, "sink::connect: at most one instance or payload");
        delegate_type call;
        call.template connect<Candidate>(std::forward<Type>(value_or_instance)...);
        signal->add(call);
    }

    template<auto Candidate, typename... Type>
    void disconnect(Type &&...value_or_instance) {
        static_assert(sizeof...(Type) <= 1, "sink::disconnect: at most one instance or payload");
        delegate_type target;
        target.template connect<Candidate>(std::forward<Type>(value_or_instance)...);
        signal->remove_if([&target](const delegate_type &call) { return call == target; });
    }

    // Disconnects every listener bound to this instance or payload.
    template<typename Type>
    void disconnect(Type &value_or_instance) {
        disconnect_data(&value_or_instance);
    }

    template<typename Type>
    void disconnect(Type *value_or_instance) {
        disconnect_data(value_or_instance);
    }

    // Disconnects every listener.
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

template<typename Ret, typename... Args>
sink(sigh<Ret(Args...)> &) -> sink<sigh<Ret(Args...)>>;

} // namespace edyn

#endif // EDYN_ECS_SINK_HPP
