// The three kinds of friction against their closed forms: a box sliding to a stop, a ball
// spinning to a stop about the contact normal and a ball rolling to a stop.
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

constexpr edyn::scalar g = 9.8f;

// The ground's coefficients are zero except sliding friction, so that default mixing (the
// geometric mean for sliding, the larger value for rolling and spinning) gives the body's own.
void make_ground(edyn::registry &registry, edyn::scalar friction) {
    auto def = edyn::rigidbody_def();
    def.kind = edyn::rigidbody_kind::rb_static;
    def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    def.material->friction = friction;
    edyn::make_rigidbody(registry, def);
}

bool report(bool ok, const char *what, edyn::scalar measured, edyn::scalar expected, const char *formula) {
    std::printf("%-36s %.3f (expected %s = %.3f)%s\n", what, measured, formula, expected,
                ok ? "" : "  <-- wrong");
    return ok;
}

// Sliding at v with friction mu decelerates at mu g: it stops after v^2 / (2 mu g).
bool sliding() {
    edyn::registry registry;
    edyn::attach(registry);
    const edyn::scalar mu = 0.4f, v = 5;
    make_ground(registry, mu);
    auto def = edyn::rigidbody_def();
    def.shape = edyn::box_shape{0.5, 0.5, 0.5};
    def.position = {0, 0.5, 0};
    def.linvel = {v, 0, 0};
    def.material->friction = mu;
    auto box = edyn::make_rigidbody(registry, def);
    for (int step = 0; step < 120; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto slid = registry.get<edyn::position>(box).x;
    auto expected = v * v / (2 * mu * g);
    edyn::detach(registry);
    return report(std::abs(slid - expected) < 0.03f * expected, "box slid (m):", slid, expected,
                  "v^2 / (2 mu g)");
}

// Spinning friction is a torque s m g about the normal (s in metres): a ball of inertia
// I = 2/5 m r^2 spinning at w stops after w I / (s m g).
bool spinning() {
    edyn::registry registry;
    edyn::attach(registry);
    make_ground(registry, 0.5);
    const edyn::scalar r = 0.5, m = 1, w = 10, s = 0.05f;
    auto def = edyn::rigidbody_def();
    def.mass = m;
    def.shape = edyn::sphere_shape{r};
    def.position = {0, r, 0};
    def.angvel = {0, w, 0};
    def.material->spin_friction = s;
    auto ball = edyn::make_rigidbody(registry, def);
    double stopped_at = 0;
    for (int step = 0; step < 300 && stopped_at == 0; ++step) {
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        if (registry.get<edyn::angvel>(ball).y < 1e-3f) stopped_at = edyn::get_simulation_time(registry);
    }
    auto expected = w * 0.4f * m * r * r / (s * m * g);
    edyn::detach(registry);
    return report(std::abs(edyn::scalar(stopped_at) - expected) < 0.03f * expected,
                  "spinning ball stopped after (s):", edyn::scalar(stopped_at), expected, "w I / (s m g)");
}

// Rolling friction is a torque c m g against rolling (c in metres; a coefficient of rolling
// resistance times the radius). A ball rolling without slipping then decelerates at
// c g / (1.4 r), the 1.4 being 1 + I / (m r^2), and stops after v^2 / (2 a).
bool rolling() {
    edyn::registry registry;
    edyn::attach(registry);
    make_ground(registry, 1);
    const edyn::scalar r = 0.5, v = 1, c = 0.05f;
    auto def = edyn::rigidbody_def();
    def.shape = edyn::sphere_shape{r};
    def.position = {0, r, 0};
    def.linvel = {v, 0, 0};
    def.angvel = {0, 0, -v / r}; // already rolling
    def.material->friction = 1;
    def.material->roll_friction = c;
    def.sleeping_disabled = true;
    auto ball = edyn::make_rigidbody(registry, def);
    auto a = c * g / (1.4f * r);
    for (int step = 0; step < 60 * 2; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto rolled = registry.get<edyn::position>(ball).x;
    auto expected = v * v / (2 * a);
    edyn::detach(registry);
    return report(std::abs(rolled - expected) < 0.03f * expected, "rolling ball stopped after (m):", rolled,
                  expected, "v^2 / (2 c g / 1.4 r)");
}

} // namespace

int main() {
    int failures = 0;
    for (auto example : {sliding, spinning, rolling})
        failures += example() ? 0 : 1;
    return failures == 0 ? 0 : 1;
}
