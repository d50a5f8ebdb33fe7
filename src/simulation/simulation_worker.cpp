#include "simulation_worker.hpp"
#include "clock.hpp"
#include "edyn/constraints/constraint_base.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/simulation/step.hpp"
#include "edyn/simulation/world.hpp"
#include "edyn/simulation/world_state.hpp"
#include <exception>
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

void on_destroy_remote(worker_context &w, registry &reg, entity e) {
    auto main = reg.get<remote_entity>(e).value;
    w.to_worker.erase(main);
    auto &record = w.message.records.emplace_back();
    record.type = worker_record::kind::entity_destroyed;
    record.main_entity = main;
}

// The manifold with its bodies named as the main side knows them.
contact_manifold main_side(const worker_context &w, const contact_manifold &manifold) {
    auto copy = manifold;
    copy.body = {w.main_of(manifold.body[0]), w.main_of(manifold.body[1])};
    return copy;
}

void record_manifold_created(worker_context &w, registry &reg, entity e) {
    auto &record = w.message.records.emplace_back();
    record.type = worker_record::kind::manifold_created;
    record.worker_entity = e;
    record.manifold = main_side(w, reg.get<contact_manifold>(e));
}

void record_manifold_destroyed(worker_context &w, registry &, entity e) {
    auto &record = w.message.records.emplace_back();
    record.type = worker_record::kind::manifold_destroyed;
    record.worker_entity = e;
}

void record_event(worker_context &w, contact_events::kind type, entity manifold,
                  contact_manifold::id_type id) {
    auto &record = w.message.records.emplace_back();
    record.type = worker_record::kind::contact_event;
    record.worker_entity = manifold;
    record.event = {type, manifold, id};
    if (auto *m = w.reg.try_get<contact_manifold>(manifold)) record.manifold = main_side(w, *m);
}

void on_started(worker_context &w, entity m) { record_event(w, contact_events::kind::started, m, 0); }
void on_ended(worker_context &w, entity m) { record_event(w, contact_events::kind::ended, m, 0); }
void on_point_created(worker_context &w, entity m, contact_manifold::id_type id) {
    record_event(w, contact_events::kind::point_created, m, id);
}
void on_point_destroyed(worker_context &w, entity m, contact_manifold::id_type id) {
    record_event(w, contact_events::kind::point_destroyed, m, id);
}

void record_slept(worker_context &w, registry &, entity e) { w.slept.push_back(e); }

// A body made static moves no more and no later step sends it: it goes once, as it stands.
void record_made_static(worker_context &w, registry &, entity e) { w.fixed.push_back(e); }

void record_woke(worker_context &w, registry &reg, entity e) {
    if (auto *remote = reg.try_get<remote_entity>(e)) w.message.woke.push_back(remote->value);
}

} // namespace

worker_context::worker_context() {
    init_config config;
    config.execution_mode = execution_mode::sequential;
    attach(reg, config);
    reg.on_destroy<remote_entity>().connect<&on_destroy_remote>(*this);
    reg.on_construct<contact_manifold>().connect<&record_manifold_created>(*this);
    reg.on_destroy<contact_manifold>().connect<&record_manifold_destroyed>(*this);
    reg.on_construct<sleeping_tag>().connect<&record_slept>(*this);
    reg.on_construct<static_tag>().connect<&record_made_static>(*this);
    reg.on_destroy<sleeping_tag>().connect<&record_woke>(*this);
}

void worker_context::send_events(bool on) {
    if (on == sends_events) return;
    sends_events = on;
    // The narrowphase records events only while someone listens: connected only when the main
    // side has listeners, so that a program without any pays nothing for them.
    if (on) {
        on_contact_started(reg).connect<&on_started>(*this);
        on_contact_ended(reg).connect<&on_ended>(*this);
        on_contact_point_created(reg).connect<&on_point_created>(*this);
        on_contact_point_destroyed(reg).connect<&on_point_destroyed>(*this);
    } else {
        on_contact_started(reg).disconnect<&on_started>(*this);
        on_contact_ended(reg).disconnect<&on_ended>(*this);
        on_contact_point_created(reg).disconnect<&on_point_created>(*this);
        on_contact_point_destroyed(reg).disconnect<&on_point_destroyed>(*this);
    }
}

entity worker_context::local(entity main) {
    auto e = find(main);
    if (e != null) return e;
    e = reg.create();
    reg.emplace<remote_entity>(e, main);
    to_worker.insert(main, e);
    return e;
}

entity worker_context::find(entity main) const noexcept {
    auto e = to_worker.find(main);
    return e != null && reg.valid(e) ? e : entity{null};
}

entity worker_context::main_of(entity worker) const noexcept {
    if (worker == null) return null;
    auto *remote = reg.try_get<remote_entity>(worker);
    return remote ? remote->value : entity{null};
}

void worker_context::advance(double time) {
    auto &world = reg.ctx().get<world_state>();
    auto &s = get_settings(reg);
    auto steps = take_due_steps(world, s, time);
    // The main side interpolates between the last two steps' motion and shows the last one's
    // contacts: steps before those send only their records (manifolds made and destroyed,
    // events, sleeping).
    for (std::uint64_t i = 0; i < steps; ++i) {
        auto dt = s.fixed_dt;
        run_one_step();
        // A step callback may have paused the world or changed its step.
        steps = i + 1 + recount_due_steps(world, s, i + 1, steps - i - 1, dt);
        send_step(i + 2 >= steps, i + 1 == steps, false);
    }
    if (steps == 0) {
        message.has_alpha = true;
        message.alpha = present_fraction(world, s);
    }
}

void worker_context::step_once() {
    run_one_step();
    send_step(true, true, true);
}

void worker_context::run_one_step() {
    // A step callback may change the settings or pause the world: the main side adopts that.
    auto controls = world_controls{get_settings(reg), is_paused(reg)};
    try {
        run_step(reg);
    } catch (const detail::entity_refusal &refusal) {
        // A refusal names the main registry's entity, as the sequential modes would.
        auto main = main_of(refusal.subject);
        auto named = main == null ? refusal.subject : main;
        message.errors.push_back(std::make_exception_ptr(
            std::invalid_argument(refusal.before + std::to_string(to_index(named)) + refusal.after)));
    } catch (...) {
        // A step callback threw: the main thread rethrows it from update(). The step stops
        // where it threw; the worker goes on with the next.
        message.errors.push_back(std::current_exception());
    }
    auto now = world_controls{get_settings(reg), is_paused(reg)};
    if (now != controls) message.controls = now;
    auto &world = reg.ctx().get<world_state>();
    message.stepped = true;
    message.simulation_time = world.simulation_time;
    message.step_count = world.step_count;
}

void worker_context::send_step(bool motion, bool contacts, bool single) {
    if (motion) snapshot_motion();
    if (contacts) {
        snapshot_contacts();
        // The batch's last step: where the present lies between its motion and the step before
        // goes in the same message. Sent apart, the main side could take this motion with the
        // last batch's fraction, near 1, and the present stepped back at the next update().
        message.has_alpha = true;
        message.alpha =
            single ? scalar(1) : present_fraction(reg.ctx().get<world_state>(), get_settings(reg));
    }
    finish_message();
}

void worker_context::snapshot_motion() {
    message.has_motion = true;
    auto add_body = [&](entity, const remote_entity &remote, const position &pos, const orientation &orn,
                        const linvel &v, const angvel &w) {
        message.bodies.push_back({remote.value, pos, orn, v, w});
    };
    reg.view<remote_entity, position, orientation, linvel, angvel>(exclude<sleeping_tag, static_tag>)
        .each(add_body);
}

void worker_context::snapshot_contacts() {
    message.has_contacts = true;
    // A manifold goes to the main side when its points changed in this step (made, dropped,
    // or the last one gone), and otherwise once every manifold_refresh_steps steps, each step
    // taking its share: copying every manifold every step would cost the main thread more
    // than the rest of update() together.
    auto &world = reg.ctx().get<world_state>();
    auto &pool = reg.storage<contact_manifold>();
    for (std::size_t i = 0; i < world.manifolds.size(); ++i) {
        auto e = world.manifolds[i];
        if (!reg.valid(e) || !pool.contains(e)) continue;
        auto changed = (world.manifold_live_slots[i] & world_state::points_changed_bit) != 0;
        auto due = (to_index(e) + world.step_count) % manifold_refresh_steps == 0;
        if (changed || (due && pool.get(e).num_points > 0)) message.manifolds.emplace_back(e, pool.get(e));
    }
    std::apply(
        [&](auto &...states) {
            auto add = [&](auto &list) {
                using constraint = typename std::decay_t<decltype(list)>::value_type::second_type;
                reg.view<remote_entity, constraint>(exclude<sleeping_tag>)
                    .each([&](entity, const remote_entity &remote, const constraint &con) {
                        list.emplace_back(remote.value, con);
                    });
            };
            (add(states), ...);
        },
        message.constraints);
}

void worker_context::finish_message() {
    // What fell asleep rests where it is now, and no later step will send it: its last state
    // goes with every message, whatever the main side skips.
    for (auto e : slept) {
        if (!reg.valid(e) || !reg.all_of<sleeping_tag>(e)) continue;
        if (auto *manifold = reg.try_get<contact_manifold>(e))
            message.rested_manifolds.emplace_back(e, *manifold);
        auto *remote = reg.try_get<remote_entity>(e);
        if (!remote) continue;
        message.slept.push_back(remote->value);
        std::apply(
            [&](auto &...lists) {
                auto add = [&](auto &list) {
                    using constraint = typename std::decay_t<decltype(list)>::value_type::second_type;
                    if (auto *con = reg.try_get<constraint>(e)) list.emplace_back(remote->value, *con);
                };
                (add(lists), ...);
            },
            message.rested_constraints);
        if (reg.all_of<position, orientation, linvel, angvel>(e)) {
            message.rested.push_back({remote->value, reg.get<position>(e), reg.get<orientation>(e),
                                      reg.get<linvel>(e), reg.get<angvel>(e)});
        }
    }
    slept.clear();
    for (auto e : fixed) {
        auto *remote = reg.valid(e) ? reg.try_get<remote_entity>(e) : nullptr;
        if (!remote || !reg.all_of<static_tag, position, orientation, linvel, angvel>(e)) continue;
        message.rested.push_back({remote->value, reg.get<position>(e), reg.get<orientation>(e),
                                  reg.get<linvel>(e), reg.get<angvel>(e)});
    }
    fixed.clear();
    if (message.empty()) return;
    message.ops_applied = ops_applied;
    publish(std::move(message));
    message = {};
}

simulation_worker::simulation_worker() {
    // Each message is handed over as soon as it is finished, so that the main side receives a
    // step while the worker runs the next.
    context.publish = [this](worker_message &&message) {
        std::lock_guard lock(mutex);
        outbox.push_back(std::move(message));
    };
    thread = std::thread([this] { run(); });
}

simulation_worker::~simulation_worker() {
    {
        std::lock_guard lock(mutex);
        stopping = true;
    }
    work_arrived.notify_one();
    thread.join();
}

std::uint64_t simulation_worker::send(std::vector<worker_op> &ops, std::optional<double> time) {
    std::uint64_t batch;
    {
        std::lock_guard lock(mutex);
        for (auto &op : ops)
            inbox.push_back(std::move(op));
        if (time) target_time = time;
        batch = ++batches_sent;
    }
    ops.clear();
    work_arrived.notify_one();
    return batch;
}

std::vector<worker_message> simulation_worker::receive() {
    std::vector<worker_message> messages;
    std::lock_guard lock(mutex);
    messages.swap(outbox);
    return messages;
}

void simulation_worker::wait(std::uint64_t batch) {
    std::unique_lock lock(mutex);
    batch_done.wait(lock, [&] { return batches_done >= batch; });
}

void simulation_worker::run() {
    std::vector<worker_op> ops;
    for (;;) {
        std::uint64_t batch;
        std::optional<double> time;
        {
            std::unique_lock lock(mutex);
            work_arrived.wait(lock, [&] { return stopping || batches_sent > batches_done; });
            if (stopping) return;
            ops.swap(inbox);
            time = target_time;
            target_time.reset();
            batch = batches_sent;
        }
        for (auto &op : ops) {
            ++context.ops_applied;
            try {
                op(context);
            } catch (...) {
                context.message.errors.push_back(std::current_exception());
            }
        }
        ops.clear();
        if (time) context.advance(*time);
        context.finish_message();
        {
            std::lock_guard lock(mutex);
            batches_done = batch;
        }
        batch_done.notify_all();
    }
}

} // namespace edyn
