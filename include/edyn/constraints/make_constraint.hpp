#ifndef EDYN_CONSTRAINTS_MAKE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_MAKE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/constraints/null_constraint.hpp"
#include <type_traits>
#include <utility>

namespace edyn {

// Throws std::invalid_argument unless body0 and body1 are two distinct rigid bodies (or, when
// `allow_external`, external entities).
void validate_constraint_bodies(const registry &registry, const char *type, entity body0, entity body1,
                                bool allow_external);

// Creates a constraint of type T between body0 and body1 on a new entity and returns it.
// `setup` receives the component (bodies already set) to assign pivots, frames, limits and so
// on. The result is validated before anything is created: bad bodies or fields throw
// std::invalid_argument naming the field, and leave the registry as it was. The constraint
// joins the bodies' islands and is destroyed with either body.
template<typename T, typename Setup>
entity make_constraint(registry &registry, entity body0, entity body1, Setup &&setup) {
    validate_constraint_bodies(registry, constraint_type_name<T>, body0, body1,
                               std::is_same_v<T, null_constraint>);
    T con{};
    con.body[0] = body0;
    con.body[1] = body1;
    std::forward<Setup>(setup)(con);
    // The setup may configure the constraint but not move it to other bodies.
    con.body[0] = body0;
    con.body[1] = body1;
    validate_constraint(con);
    auto e = registry.create();
    registry.emplace<T>(e, con);
    return e;
}

template<typename T>
entity make_constraint(registry &registry, entity body0, entity body1) {
    return make_constraint<T>(registry, body0, body1, [](T &) {});
}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_MAKE_CONSTRAINT_HPP
