#include "edyn/shapes/polyhedron_shape.hpp"
#include "edyn/shapes/convex_hull.hpp"
#include <stdexcept>
#include <string>

namespace edyn {

polyhedron_shape::polyhedron_shape(const std::vector<vector3> &points) {
    try {
        mesh = std::make_shared<const convex_mesh>(convex_hull(points));
    } catch (const std::invalid_argument &e) {
        std::string what = e.what();
        // Errors from the hull's own validation already name polyhedron_shape.
        if (what.rfind("polyhedron_shape", 0) == 0) throw;
        throw std::invalid_argument("polyhedron_shape: " + what);
    }
}

polyhedron_shape::polyhedron_shape(std::vector<vector3> vertices,
                                   const std::vector<std::vector<std::uint32_t>> &faces)
    : mesh(std::make_shared<const convex_mesh>(make_convex_mesh(std::move(vertices), faces))) {}

} // namespace edyn
