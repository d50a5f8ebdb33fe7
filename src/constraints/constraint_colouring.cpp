#include "edyn/constraints/constraint_colouring.hpp"
#include <algorithm>

namespace edyn {

void constraint_colouring::reset(std::span<const solver_body> bodies) {
    this->bodies = bodies;
    next_colour.clear();
    counts.clear();
}

std::uint32_t constraint_colouring::assign(solver_body_index a, solver_body_index b,
                                           std::uint32_t num_points) {
    // Whether each body moves is read once a colouring, in one pass, at its first constraint (a
    // colouring without constraints reads nothing).
    if (next_colour.size() != bodies.size()) {
        next_colour.resize(bodies.size());
        for (std::size_t i = 0; i < bodies.size(); ++i)
            next_colour[i] = moves(bodies[i]) ? 0u : does_not_move;
    }
    auto &nextA = next_colour[a], &nextB = next_colour[b];
    auto movesA = nextA != does_not_move, movesB = nextB != does_not_move;
    auto colour = std::max(movesA ? nextA : 0u, movesB ? nextB : 0u);
    if (movesA) nextA = colour + 1;
    if (movesB) nextB = colour + 1;
    if (counts.size() <= colour) counts.resize(colour + 1);
    ++counts[colour].constraints;
    counts[colour].points += num_points;
    return colour;
}

void constraint_colouring::colour_ranges(std::vector<std::uint32_t> &begin) {
    begin.clear();
    colour_count total;
    for (auto &count : counts) {
        begin.push_back(total.constraints);
        auto here = total;
        total.constraints += count.constraints;
        total.points += count.points;
        count = here; // from now on, the next free place of the colour
    }
    begin.push_back(total.constraints);
}

constraint_colouring::place constraint_colouring::next_place(std::uint32_t colour,
                                                             std::uint32_t num_points) noexcept {
    auto &next = counts[colour];
    place p{next.constraints, next.points};
    ++next.constraints;
    next.points += num_points;
    return p;
}

} // namespace edyn
