#include "edyn/config/version.hpp"

namespace edyn {

version_info version() noexcept { return {EDYN_VERSION_MAJOR, EDYN_VERSION_MINOR, EDYN_VERSION_PATCH}; }

std::string_view version_string() noexcept { return EDYN_VERSION_STRING; }

bool built_with_double_precision() noexcept {
#ifdef EDYN_DOUBLE_PRECISION
    return true;
#else
    return false;
#endif
}

} // namespace edyn
