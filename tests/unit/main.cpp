// The unit tests' runner. A test spec that matches no test case fails the run
// (Catch2 alone reports "No test cases matched" and exits 0), so a test that
// ctest cannot reach by its name is a failure, not a silent pass.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
    Catch::Session session;
    if (const int rc = session.applyCommandLine(argc, argv); rc != 0) return rc;
    auto& data = session.configData();
    data.warnings = static_cast<Catch::WarnAbout::What>(data.warnings | Catch::WarnAbout::NoTests);
    return session.run();
}
