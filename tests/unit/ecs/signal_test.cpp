#include "ecs_test_support.hpp"
#include "edyn/ecs/delegate.hpp"
#include "edyn/ecs/sigh.hpp"
#include "edyn/ecs/sink.hpp"
#include <gtest/gtest.h>
#include <string>
#include <type_traits>
#include <vector>

using namespace edyn;

namespace {

int twice(int x) { return 2 * x; }
int sum_with(const int &payload, int x) { return payload + x; }
int sum_with_pointer(int *payload, int x) { return *payload + x; }
void noexcept_function(int &out) noexcept { out = 7; }

struct accumulator {
    int total{0};
    int add(int x) { return total += x; }
    int peek(int x) const { return total + x; }
};

std::vector<std::string> *journal = nullptr;

void log_a(int x) { journal->push_back("a" + std::to_string(x)); }
void log_b(int x) { journal->push_back("b" + std::to_string(x)); }

struct listener {
    std::string label;
    std::vector<std::string> *out;
    void on(int x) { out->push_back(label + std::to_string(x)); }
    void other(int x) { out->push_back(label + "-other" + std::to_string(x)); }
};

struct journal_scope {
    std::vector<std::string> entries;
    journal_scope() { journal = &entries; }
    ~journal_scope() { journal = nullptr; }
};

} // namespace

TEST(delegate_test, free_function) {
    delegate<int(int)> d;
    EXPECT_FALSE(d);
    d.connect<&twice>();
    EXPECT_TRUE(d);
    EXPECT_EQ(d(21), 42);
    EXPECT_EQ(d.data(), nullptr);
    d.reset();
    EXPECT_FALSE(d);
}

TEST(delegate_test, member_function_by_reference_and_by_pointer) {
    accumulator acc;
    delegate<int(int)> by_ref;
    by_ref.connect<&accumulator::add>(acc);
    EXPECT_EQ(by_ref(3), 3);
    delegate<int(int)> by_ptr;
    by_ptr.connect<&accumulator::add>(&acc);
    EXPECT_EQ(by_ptr(4), 7);
    EXPECT_EQ(acc.total, 7);
    EXPECT_EQ(by_ref.data(), &acc);
    const accumulator &cacc = acc;
    delegate<int(int)> on_const;
    on_const.connect<&accumulator::peek>(cacc);
    EXPECT_EQ(on_const(1), 8);
}

TEST(delegate_test, free_function_with_payload) {
    int payload = 10;
    delegate<int(int)> by_ref;
    by_ref.connect<&sum_with>(payload);
    EXPECT_EQ(by_ref(5), 15);
    delegate<int(int)> by_ptr;
    by_ptr.connect<&sum_with_pointer>(&payload);
    payload = 20;
    EXPECT_EQ(by_ptr(5), 25);
    EXPECT_EQ(by_ref(5), 25) << "the payload is referenced, not copied";
}

TEST(delegate_test, connect_arg_constructors_and_deduction) {
    delegate<int(int)> d{connect_arg<&twice>};
    EXPECT_EQ(d(4), 8);
    auto deduced = delegate(connect_arg_t<&twice>{});
    static_assert(std::is_same_v<decltype(deduced), delegate<int(int)>>);
    EXPECT_EQ(deduced(5), 10);
    accumulator acc;
    auto bound = delegate(connect_arg_t<&accumulator::add>{}, acc);
    static_assert(std::is_same_v<decltype(bound), delegate<int(int)>>);
    EXPECT_EQ(bound(2), 2);
    int payload = 1;
    auto with_payload = delegate{connect_arg<&sum_with>, payload};
    static_assert(std::is_same_v<decltype(with_payload), delegate<int(int)>>);
    EXPECT_EQ(with_payload(2), 3);
    auto from_noexcept = delegate{connect_arg<&noexcept_function>};
    static_assert(std::is_same_v<decltype(from_noexcept), delegate<void(int &)>>);
    int out = 0;
    from_noexcept(out);
    EXPECT_EQ(out, 7);
}

TEST(delegate_test, equality_compares_function_and_instance) {
    accumulator a, b;
    delegate<int(int)> x{connect_arg<&accumulator::add>, a};
    delegate<int(int)> y{connect_arg<&accumulator::add>, a};
    delegate<int(int)> z{connect_arg<&accumulator::add>, b};
    delegate<int(int)> w{connect_arg<&twice>};
    EXPECT_TRUE(x == y);
    EXPECT_FALSE(x == z);
    EXPECT_FALSE(x == w);
    EXPECT_TRUE(delegate<int(int)>{} == delegate<int(int)>{});
}

TEST(delegate_test, runtime_function_pointer_and_payload) {
    int payload = 3;
    delegate<int(int)> d;
    d.connect([](const void *data, int x) { return *static_cast<const int *>(data) * x; }, &payload);
    EXPECT_EQ(d(5), 15);
}

TEST(sigh_test, publish_calls_listeners_in_connection_order) {
    journal_scope scope;
    sigh<void(int)> signal;
    EXPECT_TRUE(signal.empty());
    sink sink{signal};
    sink.connect<&log_b>();
    sink.connect<&log_a>();
    EXPECT_EQ(signal.size(), 2u);
    EXPECT_FALSE(sink.empty());
    signal.publish(1);
    EXPECT_EQ(scope.entries, (std::vector<std::string>{"b1", "a1"}));
}

TEST(sigh_test, connecting_twice_keeps_one_connection) {
    journal_scope scope;
    sigh<void(int)> signal;
    sink sink{signal};
    listener l{"l", &scope.entries};
    sink.connect<&log_a>();
    sink.connect<&log_a>();
    sink.connect<&listener::on>(l);
    sink.connect<&listener::on>(l);
    sink.connect<&listener::on>(&l);
    EXPECT_EQ(signal.size(), 2u);
    signal.publish(2);
    EXPECT_EQ(scope.entries, (std::vector<std::string>{"a2", "l2"}));
}

TEST(sigh_test, disconnect_one_an_instance_or_all) {
    journal_scope scope;
    sigh<void(int)> signal;
    sink sink{signal};
    listener l{"l", &scope.entries};
    listener m{"m", &scope.entries};
    sink.connect<&log_a>();
    sink.connect<&listener::on>(l);
    sink.connect<&listener::other>(l);
    sink.connect<&listener::on>(m);
    EXPECT_EQ(signal.size(), 4u);

    sink.disconnect<&listener::on>(m);
    EXPECT_EQ(signal.size(), 3u);
    sink.disconnect<&listener::on>(m);
    EXPECT_EQ(signal.size(), 3u) << "disconnecting what is not connected does nothing";

    sink.disconnect(l);
    EXPECT_EQ(signal.size(), 1u) << "every listener bound to l";
    signal.publish(3);
    EXPECT_EQ(scope.entries, (std::vector<std::string>{"a3"}));

    sink.connect<&listener::on>(&m);
    sink.disconnect(&m);
    EXPECT_EQ(signal.size(), 1u);

    sink.connect<&log_b>();
    sink.disconnect<&log_a>();
    EXPECT_EQ(signal.size(), 1u);
    sink.disconnect();
    EXPECT_TRUE(signal.empty());
    scope.entries.clear();
    signal.publish(4);
    EXPECT_TRUE(scope.entries.empty());
}

namespace {

struct self_disconnecting {
    sigh<void(int)> *signal;
    std::vector<std::string> *out;
    std::string label;
    bool disconnect_all{false};
    void on(int x) {
        out->push_back(label + std::to_string(x));
        if (disconnect_all) {
            sink{*signal}.disconnect();
        } else {
            sink{*signal}.disconnect<&self_disconnecting::on>(*this);
        }
    }
};

struct connects_during_publish {
    sigh<void(int)> *signal;
    void on(int) { sink{*signal}.connect<&log_b>(); }
};

struct republisher {
    sigh<void(int)> *signal;
    void on(int x) {
        if (x > 0) {
            signal->publish(x - 1);
        }
    }
};

} // namespace

TEST(sigh_test, listener_may_disconnect_itself_during_publish) {
    journal_scope scope;
    sigh<void(int)> signal;
    self_disconnecting once{&signal, &scope.entries, "once"};
    sink{signal}.connect<&log_a>();
    sink{signal}.connect<&self_disconnecting::on>(once);
    sink{signal}.connect<&log_b>();
    signal.publish(1);
    EXPECT_EQ(signal.size(), 2u);
    signal.publish(2);
    EXPECT_EQ(scope.entries, (std::vector<std::string>{"a1", "once1", "b1", "a2", "b2"}));
}

TEST(sigh_test, listener_disconnected_during_publish_is_not_called_by_it) {
    journal_scope scope;
    sigh<void(int)> signal;
    self_disconnecting clearer{&signal, &scope.entries, "clear", true};
    sink{signal}.connect<&log_a>();
    sink{signal}.connect<&self_disconnecting::on>(clearer);
    sink{signal}.connect<&log_b>();
    signal.publish(1);
    EXPECT_EQ(scope.entries, (std::vector<std::string>{"a1", "clear1"}))
        << "b was disconnected before its turn";
    EXPECT_TRUE(signal.empty());
    signal.publish(2);
    EXPECT_EQ(scope.entries.size(), 2u);
}

TEST(sigh_test, listener_connected_during_publish_waits_for_the_next_one) {
    journal_scope scope;
    sigh<void(int)> signal;
    connects_during_publish connector{&signal};
    sink{signal}.connect<&connects_during_publish::on>(connector);
    signal.publish(1);
    EXPECT_TRUE(scope.entries.empty());
    EXPECT_EQ(signal.size(), 2u);
    signal.publish(2);
    EXPECT_EQ(scope.entries, (std::vector<std::string>{"b2"}));
}

TEST(sigh_test, nested_publish) {
    journal_scope scope;
    sigh<void(int)> signal;
    republisher again{&signal};
    sink{signal}.connect<&log_a>();
    sink{signal}.connect<&republisher::on>(again);
    signal.publish(2);
    EXPECT_EQ(scope.entries, (std::vector<std::string>{"a2", "a1", "a0"}));
}

TEST(sigh_test, disconnect_during_nested_publish) {
    journal_scope scope;
    sigh<void(int)> signal;
    republisher again{&signal};
    self_disconnecting once{&signal, &scope.entries, "once"};
    sink{signal}.connect<&republisher::on>(again);
    sink{signal}.connect<&self_disconnecting::on>(once);
    sink{signal}.connect<&log_a>();
    signal.publish(1);
    // Outer publish(1) runs republisher -> inner publish(0): once0 (disconnects), a0; back in
    // the outer publish `once` is gone, then a1.
    EXPECT_EQ(scope.entries, (std::vector<std::string>{"once0", "a0", "a1"}));
    EXPECT_EQ(signal.size(), 2u);
}
