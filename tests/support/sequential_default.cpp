// Linked into the unit test programs: they check what each function does in the calling
// thread, so attach(registry) without a configuration gives them the sequential mode there.
// The behaviour suite runs in every mode (behaviour_support.hpp), and the asynchronous mode has
// unit tests of its own that ask for it explicitly.
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>

namespace {

struct sequential_default : ::testing::Environment {
    void SetUp() override {
        edyn::init_config config;
        config.execution_mode = edyn::execution_mode::sequential;
        edyn::init(config);
    }
};

const auto *registered = ::testing::AddGlobalTestEnvironment(new sequential_default);

} // namespace
