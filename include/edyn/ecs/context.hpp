#ifndef EDYN_ECS_CONTEXT_HPP
#define EDYN_ECS_CONTEXT_HPP

#include "edyn/config/assert.hpp"
#include "edyn/ecs/construct.hpp"
#include "edyn/ecs/type_info.hpp"
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace edyn {

// Context variables of a registry (`registry.ctx()`): at most one value per type, owned by the
// context, for state that belongs to a registry as a whole rather than to an entity. Values are
// allocated one by one and never move: references stay valid until that value is erased or the
// context is destroyed. Values are destroyed in the reverse order of their creation, so a value
// may refer to values created before it.
class context {
public:
    context() = default;
    context(const context &) = delete;
    context &operator=(const context &) = delete;
    context(context &&) noexcept = default;
    context &operator=(context &&other) noexcept {
        if (this != &other) {
            clear();
            entries = std::move(other.entries);
            slots = std::move(other.slots);
        }
        return *this;
    }
    ~context() { clear(); }

    // Creates the value of type `Type` from `args` and returns it; if there already is one, it
    // is returned unchanged and `args` are ignored (as EnTT does).
    template<typename Type, typename... Args>
    Type &emplace(Args &&...args) {
        if (auto *existing = find<Type>()) {
            return *existing;
        }
        return insert<Type>(std::forward<Args>(args)...);
    }

    // Creates the value or replaces the existing one with a new value built from `args`.
    template<typename Type, typename... Args>
    Type &emplace_or_replace(Args &&...args) {
        if (auto *existing = find<Type>()) {
            *existing = detail::make_component<Type>(std::forward<Args>(args)...);
            return *existing;
        }
        return insert<Type>(std::forward<Args>(args)...);
    }

    template<typename Type>
    Type &insert_or_assign(Type &&value) {
        return emplace_or_replace<std::remove_cvref_t<Type>>(std::forward<Type>(value));
    }

    template<typename Type>
    [[nodiscard]] Type *find() noexcept {
        const auto id = type_index<Type>();
        if (id >= slots.size() || slots[id] == no_slot) {
            return nullptr;
        }
        return static_cast<Type *>(entries[slots[id]].value.get());
    }

    template<typename Type>
    [[nodiscard]] const Type *find() const noexcept {
        return const_cast<context *>(this)->find<Type>();
    }

    template<typename Type>
    [[nodiscard]] Type &get() noexcept {
        auto *value = find<Type>();
        EDYN_ASSERT(value != nullptr, "context::get: no context variable of this type");
        return *value;
    }

    template<typename Type>
    [[nodiscard]] const Type &get() const noexcept {
        return const_cast<context *>(this)->get<Type>();
    }

    template<typename Type>
    [[nodiscard]] bool contains() const noexcept {
        return find<Type>() != nullptr;
    }

    // Destroys the value of type `Type`; returns whether there was one.
    template<typename Type>
    bool erase() {
        const auto id = type_index<Type>();
        if (id >= slots.size() || slots[id] == no_slot) {
            return false;
        }
        const auto pos = slots[id];
        // Unlink first: the value's destructor may look at the context.
        auto removed = std::move(entries[pos]);
        entries.erase(entries.begin() + static_cast<std::ptrdiff_t>(pos));
        slots[id] = no_slot;
        for (auto &slot : slots) {
            if (slot != no_slot && slot > pos) {
                --slot;
            }
        }
        return true;
    }

    [[nodiscard]] std::size_t size() const noexcept { return entries.size(); }
    [[nodiscard]] bool empty() const noexcept { return entries.empty(); }

    // Destroys every value, newest first.
    void clear() noexcept {
        while (!entries.empty()) {
            auto removed = std::move(entries.back());
            entries.pop_back();
            slots[removed.id] = no_slot;
        }
    }

private:
    static constexpr std::size_t no_slot = ~std::size_t{};

    using deleter_type = void (*)(void *);

    struct entry {
        std::unique_ptr<void, deleter_type> value;
        std::size_t id;
    };

    template<typename Type, typename... Args>
    Type &insert(Args &&...args) {
        static_assert(std::is_same_v<Type, std::remove_cvref_t<Type>>,
                      "context: variable types must not be references or cv-qualified");
        const auto id = type_index<Type>();
        if (id >= slots.size()) {
            slots.resize(id + 1, no_slot);
        }
        entries.reserve(entries.size() + 1);
        auto value =
            std::unique_ptr<Type>(new Type(detail::make_component<Type>(std::forward<Args>(args)...)));
        auto *pointer = value.get();
        entries.push_back({std::unique_ptr<void, deleter_type>(value.release(), &destroy<Type>), id});
        slots[id] = entries.size() - 1;
        return *pointer;
    }

    template<typename Type>
    static void destroy(void *value) noexcept {
        delete static_cast<Type *>(value);
    }

    std::vector<entry> entries;     // in order of creation
    std::vector<std::size_t> slots; // by type index: position in `entries`, or `no_slot`
};

} // namespace edyn

#endif // EDYN_ECS_CONTEXT_HPP
