#pragma once
// What a test does when a component it needs (a PostgreSQL server, a locale, MuJoCo, a
// privilege) is missing (tests/common/as_user.h: how a test run as root checks file
// permissions, as the user "nobody").
//
// Outside CI a missing component skips the test with the reason. Under CI (CI=true, as
// .ci/run sets it) it fails: CI installs every component (scripts/install-deps.sh), so a
// missing one there is a broken set-up, never a test to pass over.

#include <cstdlib>
#include <cstring>
#include <initializer_list>

namespace padrob_test {

/// True under CI (the environment variable CI is "true" or "1").
inline bool underCi()
{
    const char* ci = std::getenv("CI");
    return ci && (std::strcmp(ci, "true") == 0 || std::strcmp(ci, "1") == 0);
}

}  // namespace padrob_test

/// GoogleTest: skips the test with `why` (streamable) outside CI, fails it under CI.
/// (One statement, as GTEST_SKIP() is, so that it can follow an `if` without braces.)
#define PADROB_NEEDS_COMPONENT(why)                                                                                \
    return ::testing::internal::AssertHelper(::padrob_test::underCi() ? ::testing::TestPartResult::kFatalFailure   \
                                                                      : ::testing::TestPartResult::kSkip,          \
                                             __FILE__, __LINE__,                                                   \
                                             ::padrob_test::underCi()                                              \
                                                 ? "under CI a missing component fails the test"                   \
                                                 : "Skipped") = ::testing::Message() << why

