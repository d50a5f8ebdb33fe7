#include "edyn/constraints/make_constraint.hpp"
#include "edyn/constraints/external_entity.hpp"
#include "edyn/dynamics/tags.hpp"
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

std::string describe(entity e) {
    return "entity " + std::to_string(to_index(e)) + " (version " + std::to_string(to_version(e)) + ")";
}

} // namespace

void validate_constraint_bodies(const registry &registry, const char *type, entity body0, entity body1,
                                bool allow_external, bool require_dynamic) {
    const entity bodies[2]{body0, body1};
    const char *fields[2]{"body[0]", "body[1]"};
    for (int i = 0; i < 2; ++i) {
        if (bodies[i] == null || !registry.valid(bodies[i])) {
            throw_constraint_error(type, fields[i], "must be a valid entity, got " + describe(bodies[i]));
        }
        bool accepted = registry.all_of<rigidbody_tag>(bodies[i]) ||
                        (allow_external && registry.all_of<external_tag>(bodies[i]));
        if (!accepted) {
            throw_constraint_error(type, fields[i],
                                   std::string("must be a rigid body") +
                                       (allow_external ? " or an external entity" : "") + ", got " +
                                       describe(bodies[i]));
        }
        if (require_dynamic && !registry.all_of<dynamic_tag>(bodies[i])) {
            throw_constraint_error(type, fields[i],
                                   "must be a dynamic rigid body (both bodies must be dynamic: static and "
                                   "kinematic bodies have no finite mass to attract with), got " +
                                       describe(bodies[i]));
        }
    }
    if (body0 == body1) {
        throw_constraint_error(type, "body[1]",
                               "must differ from body[0], got " + describe(body1) + " twice");
    }
}

} // namespace edyn
