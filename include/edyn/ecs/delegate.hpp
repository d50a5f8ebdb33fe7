#ifndef EDYN_ECS_DELEGATE_HPP
#define EDYN_ECS_DELEGATE_HPP

#include "edyn/config/assert.hpp"
#include <functional>
#include <type_traits>
#include <utility>

namespace edyn {

// Tag that names a function at compile time, to construct a delegate bound to it:
// `edyn::delegate<void(int)>{edyn::connect_arg<&fn>}` or
// `edyn::delegate{edyn::connect_arg_t<&fn>{}}`.
template<auto Candidate>
struct connect_arg_t {
    explicit connect_arg_t() = default;
};

template<auto Candidate>
inline constexpr connect_arg_t<Candidate> connect_arg{};

template<typename>
class delegate;

// A non-owning handle to a function known at compile time, optionally bound to an object: a
// free function, a member function called on an instance, or a free function that receives a
// payload as its first argument. It is two pointers wide, copies freely and never allocates;
// the caller keeps the instance or payload alive while the delegate may be called.
//
//   delegate<int(int)> d;
//   d.connect<&free_function>();              // free_function(int)
//   d.connect<&my_class::member>(object);      // object.member(int); object by reference or
//   pointer d.connect<&with_payload>(payload);         // with_payload(payload, int); payload as
//   the
//                                              // function takes it, by reference or pointer
template<typename Ret, typename... Args>
class delegate<Ret(Args...)> {
public:
    using function_type = Ret(const void *, Args...);
    using result_type = Ret;

    delegate() noexcept = default;

    // A delegate bound to a function given by a runtime pointer and an opaque payload.
    delegate(function_type *function, const void *payload = nullptr) noexcept
        : function(function)
        , instance(payload) {}

    template<auto Candidate>
    delegate(connect_arg_t<Candidate>) noexcept {
        connect<Candidate>();
    }

    template<auto Candidate, typename Type>
    delegate(connect_arg_t<Candidate>, Type &&value_or_instance) noexcept {
        connect<Candidate>(std::forward<Type>(value_or_instance));
    }

    template<auto Candidate>
    void connect() noexcept {
        static_assert(std::is_invocable_r_v<Ret, decltype(Candidate), Args...>,
                      "delegate::connect: candidate cannot be called with these arguments");
        instance = nullptr;
        function = [](const void *, Args... args) -> Ret {
            return static_cast<Ret>(std::invoke(Candidate, std::forward<Args>(args)...));
        };
    }

    // `Candidate` is called as `std::invoke(Candidate, value, args...)`, which covers member
    // functions (value is the object) and free functions taking the payload by reference.
    template<auto Candidate, typename Type>
    void connect(Type &value_or_instance) noexcept {
        static_assert(std::is_invocable_r_v<Ret, decltype(Candidate), Type &, Args...>,
                      "delegate::connect: candidate cannot be called with this instance and arguments");
        instance = &value_or_instance;
        function = [](const void *payload, Args... args) -> Ret {
            auto *typed = static_cast<Type *>(const_cast<void *>(payload));
            return static_cast<Ret>(std::invoke(Candidate, *typed, std::forward<Args>(args)...));
        };
    }

    // As above, with the instance or payload passed on as a pointer. A member function bound
    // through a pointer is the same delegate as one bound through a reference to the object.
    template<auto Candidate, typename Type>
    void connect(Type *value_or_instance) noexcept {
        if constexpr (std::is_member_pointer_v<decltype(Candidate)>) {
            EDYN_ASSERT(value_or_instance != nullptr, "delegate::connect: null instance");
            connect<Candidate>(*value_or_instance);
        } else {
            static_assert(std::is_invocable_r_v<Ret, decltype(Candidate), Type *, Args...>,
                          "delegate::connect: candidate cannot be called with this pointer and arguments");
            instance = value_or_instance;
            function = [](const void *payload, Args... args) -> Ret {
                auto *typed = static_cast<Type *>(const_cast<void *>(payload));
                return static_cast<Ret>(std::invoke(Candidate, typed, std::forward<Args>(args)...));
            };
        }
    }

    void connect(function_type *fn, const void *payload = nullptr) noexcept {
        function = fn;
        instance = payload;
    }

    void reset() noexcept {
        function = nullptr;
        instance = nullptr;
    }

    // The instance or payload, or null for a plain free function.
    [[nodiscard]] const void *data() const noexcept { return instance; }

    Ret operator()(Args... args) const {
        EDYN_ASSERT(function != nullptr, "delegate: called while not connected");
        return function(instance, std::forward<Args>(args)...);
    }

    [[nodiscard]] explicit operator bool() const noexcept { return function != nullptr; }

    // Two delegates are equal when they call the same candidate on the same instance.
    [[nodiscard]] friend bool operator==(const delegate &a, const delegate &b) noexcept {
        return a.function == b.function && a.instance == b.instance;
    }

private:
    function_type *function{nullptr};
    const void *instance{nullptr};
};

namespace detail {

template<typename>
struct function_signature;

template<typename Ret, typename... Args>
struct function_signature<Ret (*)(Args...)> {
    using type = Ret(Args...);
};

template<typename Ret, typename... Args>
struct function_signature<Ret (*)(Args...) noexcept> : function_signature<Ret (*)(Args...)> {};

// The signature left once the first argument is bound to a payload or instance.
template<typename>
struct bound_signature;

template<typename Ret, typename First, typename... Args>
struct bound_signature<Ret (*)(First, Args...)> {
    using type = Ret(Args...);
};

template<typename Ret, typename First, typename... Args>
struct bound_signature<Ret (*)(First, Args...) noexcept> : bound_signature<Ret (*)(First, Args...)> {};

#define EDYN_DETAIL_MEMBER_SIGNATURE(qualifiers)                                                             \
    template<typename Ret, typename Class, typename... Args>                                                 \
    struct bound_signature<Ret (Class::*)(Args...) qualifiers> {                                             \
        using type = Ret(Args...);                                                                           \
    };
EDYN_DETAIL_MEMBER_SIGNATURE()
EDYN_DETAIL_MEMBER_SIGNATURE(const)
EDYN_DETAIL_MEMBER_SIGNATURE(noexcept)
EDYN_DETAIL_MEMBER_SIGNATURE(const noexcept)
#undef EDYN_DETAIL_MEMBER_SIGNATURE

} // namespace detail

template<auto Candidate>
delegate(connect_arg_t<Candidate>)
    -> delegate<typename detail::function_signature<decltype(Candidate)>::type>;

template<auto Candidate, typename Type>
delegate(connect_arg_t<Candidate>, Type &&)
    -> delegate<typename detail::bound_signature<decltype(Candidate)>::type>;

} // namespace edyn

#endif // EDYN_ECS_DELEGATE_HPP
