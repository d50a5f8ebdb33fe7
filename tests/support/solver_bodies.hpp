#ifndef EDYN_TESTS_SUPPORT_SOLVER_BODIES_HPP
#define EDYN_TESTS_SUPPORT_SOLVER_BODIES_HPP

// The solver body array the tests of contact ordering and colouring build their contacts on.
#include "edyn/dynamics/solver_body.hpp"
#include <cstddef>
#include <vector>

namespace edyn::test {

/// Body 0 is the static body; bodies 1 to `moving` move (a unit cube of 1 kg: inverse mass 1,
/// inverse inertia 6 about each axis); the `resting` bodies after them do not move, as kinematic
/// bodies.
inline std::vector<solver_body> make_solver_bodies(std::size_t moving, std::size_t resting = 0) {
    std::vector<solver_body> bodies(1 + moving + resting);
    for (std::size_t i = 1; i <= moving; ++i) {
        bodies[i].inv_mass = 1;
        bodies[i].inv_inertia = matrix3x3_rows({6, 0, 0}, {0, 6, 0}, {0, 0, 6});
    }
    return bodies;
}

} // namespace edyn::test

#endif // EDYN_TESTS_SUPPORT_SOLVER_BODIES_HPP
