#ifndef EDYN_TESTS_JOINTS_SUPPORT_HPP
#define EDYN_TESTS_JOINTS_SUPPORT_HPP

#include "behaviour_support.hpp"
#include <vector>

namespace edyn::test {

// A static, amorphous body to hang joints from.
inline entity make_anchor(registry &reg, const vector3 &position) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.position = position;
    def.material.reset();
    return make_rigidbody(reg, def);
}

// World-space position of a pivot given in the body's object space (relative to its origin).
inline vector3 world_pivot(const registry &reg, entity body, const vector3 &pivot) {
    return get_rigidbody_origin(reg, body) + rotate(reg.get<orientation>(body), pivot);
}

// Times at which `signal` crosses zero going up, linearly interpolated between samples.
struct crossing_timer {
    scalar previous{0};
    double previous_time{0};
    bool started{false};
    std::vector<double> times;

    void sample(double time, scalar value) {
        if (started && previous < 0 && value >= 0) {
            times.push_back(previous_time + (time - previous_time) * double(-previous / (value - previous)));
        }
        previous = value;
        previous_time = time;
        started = true;
    }

    // Mean period between the first and last crossing; 0 with fewer than two.
    double mean_period() const {
        if (times.size() < 2) return 0;
        return (times.back() - times.front()) / double(times.size() - 1);
    }
};

} // namespace edyn::test

#endif // EDYN_TESTS_JOINTS_SUPPORT_HPP
