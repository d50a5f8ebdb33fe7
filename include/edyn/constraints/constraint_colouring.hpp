#ifndef EDYN_CONSTRAINTS_CONSTRAINT_COLOURING_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_COLOURING_HPP

#include "edyn/dynamics/solver_body.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

// Colours a step's constraints, taken in the order the sequential solver visits them, so that
// no two constraints of one colour share a body that moves, and every constraint comes after
// each earlier one that shares a moving body with it. Solving the colours in turn, the
// constraints of one colour at once on any number of threads, then gives bit for bit what
// solving them one after another in the given order gives: two constraints that share no moving
// body touch no common state, and those that do keep their order. Bodies that do not move (the
// static body, kinematic bodies: see moves() in solver_body.hpp) are only read by the solver and order
// nothing. A constraint's colour is one more than the highest colour taken so far by either of
// its moving bodies, found in constant time; colouring allocates only when the world grows.
//
// The colour count is the longest run of constraints, one after another in the given order,
// that each share a body with the next: a few dozen in a pile, the whole length of a chain
// solved end to end (which then runs on one thread, as it must to give the sequential result).
class constraint_colouring {
public:
    // Starts a new colouring for these bodies, which must outlive it (only whether they move
    // is read).
    void reset(std::span<const solver_body> bodies);

    // The colour of the next constraint, between bodies a and b, with `num_points` rows of
    // storage (contact points); both are counted per colour for place().
    std::uint32_t assign(solver_body_index a, solver_body_index b, std::uint32_t num_points = 1);

    std::uint32_t num_colours() const noexcept { return static_cast<std::uint32_t>(counts.size()); }

    // Once every constraint is assigned: the first constraint index of each colour, colours in
    // order, and one past the last, written over `begin` (num_colours() + 1 entries).
    void colour_ranges(std::vector<std::uint32_t> &begin);

    // Once colour_ranges has run: the next place of a constraint of `colour` in the colour-ordered
    // arrays, and the first of its num_points points; constraints of one colour are placed in
    // the order they are asked for.
    struct place {
        std::uint32_t constraint, first_point;
    };
    place next_place(std::uint32_t colour, std::uint32_t num_points) noexcept;

private:
    struct colour_count {
        std::uint32_t constraints{0}, points{0};
    };
    std::span<const solver_body> bodies;
    std::vector<std::uint32_t> next_colour; // per body: one more than the highest colour it took
    std::vector<colour_count> counts;       // per colour, then per colour the next free place
};

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_COLOURING_HPP
