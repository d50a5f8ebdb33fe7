#include "edyn/constraints/contact_order.hpp"
#include "edyn/config/assert.hpp"
#include <algorithm>

namespace edyn {

void contact_order::reset(std::span<const solver_body> bodies) {
    this->bodies = bodies;
    pairs.clear();
}

void contact_order::add(solver_body_index a, solver_body_index b) {
    EDYN_ASSERT(a < bodies.size() && b < bodies.size(), "contact_order::add: body index out of range");
    pairs.push_back(a);
    pairs.push_back(b);
}

std::span<const std::uint32_t> contact_order::sorted() {
    auto num_bodies = bodies.size();
    auto num_contacts = static_cast<std::uint32_t>(pairs.size() / 2);

    // Each body's contacts, as the other body of each, bodies in index order...
    first_link.assign(num_bodies + 1, 0);
    for (auto body : pairs)
        ++first_link[body + 1];
    for (std::size_t i = 0; i < num_bodies; ++i)
        first_link[i + 1] += first_link[i];
    links.resize(pairs.size());
    depth.assign(first_link.begin(), first_link.end() - 1); // each body's next free link
    for (std::uint32_t k = 0; k < num_contacts; ++k) {
        auto a = pairs[2 * k], b = pairs[2 * k + 1];
        links[depth[a]++] = b;
        links[depth[b]++] = a;
    }

    // ...then every body's depth, breadth first from the bodies that do not move...
    depth.assign(num_bodies, unreached);
    queue.clear();
    for (solver_body_index i = 0; i < num_bodies; ++i) {
        if (moves(bodies[i])) continue;
        depth[i] = resting_depth;
        queue.push_back(i);
    }
    std::uint32_t max_depth = resting_depth;
    for (std::size_t q = 0; q < queue.size(); ++q) {
        auto body = queue[q];
        for (auto i = first_link[body]; i < first_link[body + 1]; ++i) {
            auto other = links[i];
            if (depth[other] != unreached) continue;
            depth[other] = depth[body] + 1;
            max_depth = std::max(max_depth, depth[other]);
            queue.push_back(other);
        }
    }

    // ...and the contacts by group, in the order added within each: group 2 d holds the
    // contacts between depths d and d + 1, group 2 d + 1 those between two bodies of depth d
    // (so that those come after the contacts up to the next depth), and the last group the
    // contacts that reach no resting body. Neighbours' depths differ by one at most.
    auto num_groups = std::size_t(2) * max_depth + 3;
    group_begin.assign(num_groups + 1, 0);
    group.resize(num_contacts);
    for (std::uint32_t k = 0; k < num_contacts; ++k) {
        auto da = depth[pairs[2 * k]], db = depth[pairs[2 * k + 1]];
        auto g = da == unreached || db == unreached ? num_groups - 1
                                                    : std::size_t(2) * std::min(da, db) + (da == db ? 1 : 0);
        group[k] = static_cast<std::uint32_t>(g);
        ++group_begin[g + 1];
    }
    for (std::size_t g = 0; g < num_groups; ++g)
        group_begin[g + 1] += group_begin[g];
    order.resize(num_contacts);
    for (std::uint32_t k = 0; k < num_contacts; ++k)
        order[group_begin[group[k]]++] = k;
    return order;
}

} // namespace edyn
