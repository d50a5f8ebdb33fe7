#ifndef EDYN_TESTS_UNIT_ECS_TEST_SUPPORT_HPP
#define EDYN_TESTS_UNIT_ECS_TEST_SUPPORT_HPP

#include "edyn/ecs/entity.hpp"
#include <ostream>
#include <string>
#include <utility>

// GoogleTest prints a scoped enumeration as raw bytes; this makes failures show "entity 5v1".
namespace edyn {
inline void PrintTo(entity e, std::ostream *os) { *os << "entity " << to_index(e) << 'v' << to_version(e); }
} // namespace edyn

// Component types shared by the ecs tests. A named namespace keeps type names readable in the
// messages the tests check.
namespace ecs_test {

struct position {
    float x{}, y{}, z{};
    friend bool operator==(const position &, const position &) = default;
};

struct velocity {
    float x{}, y{}, z{};
    friend bool operator==(const velocity &, const velocity &) = default;
};

struct mass {
    float value{};
};

struct name {
    std::string value;
};

struct tag {};
struct other_tag {};

// Counts live instances so that tests can check that pools destroy what they hold.
struct counted {
    static inline int live = 0;
    int value{};
    counted(int value = 0)
        : value(value) {
        ++live;
    }
    counted(const counted &other)
        : value(other.value) {
        ++live;
    }
    counted(counted &&other) noexcept
        : value(other.value) {
        ++live;
    }
    counted &operator=(const counted &) = default;
    counted &operator=(counted &&) noexcept = default;
    ~counted() { --live; }
};

} // namespace ecs_test

#endif // EDYN_TESTS_UNIT_ECS_TEST_SUPPORT_HPP
