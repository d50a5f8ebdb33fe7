#ifndef EDYN_CONSTRAINTS_CONTACT_ORDER_HPP
#define EDYN_CONSTRAINTS_CONTACT_ORDER_HPP

#include "edyn/dynamics/solver_body.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

/// The order in which a step's contacts are solved: outward from the bodies that do not move
/// (the static body, kinematic bodies), as weight is carried in a stack or a heap.
///
/// Each moving body's depth is the fewest contacts between it and a body that does not move
/// (found breadth first over the step's contacts). A contact between depths d and d + 1 is
/// solved before the contacts between two bodies of depth d + 1, which come before those
/// between d + 1 and d + 2, and so on; contacts of bodies that reach no resting body (a clump
/// in mid-air) come last. Within each of those groups the contacts keep the order they were
/// added in. The colouring (constraint_colouring.hpp) keeps this order: a stack is solved from
/// the ground up in every pass, and since each layer's contacts share few bodies with each
/// other, they take few colours, whose bundles are the fuller for it.
///
/// The order depends only on the contacts and the order they are added in, so that it is the
/// same on any number of threads. Nothing is allocated once the buffers have grown to the
/// world's size.
///
/// Use: reset(), add() for every contact, then sorted(). One ordering is used by one thread at a
/// time.
class contact_order {
public:
    /// Starts a new ordering for these bodies, which must outlive it (only whether they move is
    /// read).
    /// @param bodies The step's solver bodies, indexed by solver_body_index.
    void reset(std::span<const solver_body> bodies);

    /// Adds the next contact, between bodies a and b (indices in the bodies given to reset()).
    void add(solver_body_index a, solver_body_index b);

    /// The contacts added since reset(), as indices in the order they were added, in the order
    /// they are to be solved. Valid until the next reset().
    /// @return One index per contact added.
    std::span<const std::uint32_t> sorted();

    /// Depth of a body found by the last sorted(): 0 for one that does not move, the largest
    /// std::uint32_t for one that reaches none.
    /// @param body A body index in the bodies given to reset().
    /// @return Its depth.
    std::uint32_t depth_of(solver_body_index body) const { return depth[body]; }

private:
    /// Depth of a body that does not move, and the depth of those that reach none.
    static constexpr std::uint32_t resting_depth = 0;
    static constexpr std::uint32_t unreached = ~std::uint32_t(0);

    std::span<const solver_body> bodies;
    std::vector<solver_body_index> pairs;   ///< Two bodies per contact, as added.
    std::vector<std::uint32_t> first_link;  ///< Per body: where its contacts begin in `links`.
    std::vector<solver_body_index> links;   ///< Per body, the other body of each of its contacts.
    std::vector<std::uint32_t> depth;       ///< Per body (unreached until found).
    std::vector<solver_body_index> queue;   ///< The breadth-first search's bodies, in order found.
    std::vector<std::uint32_t> group;       ///< Per contact: its group.
    std::vector<std::uint32_t> group_begin; ///< Per group: where its contacts begin in `order`.
    std::vector<std::uint32_t> order;       ///< The contacts in solving order.
};

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONTACT_ORDER_HPP
