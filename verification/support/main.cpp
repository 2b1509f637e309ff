// The doctest main of every verify_<method> executable. Each ctest test runs one source file's test cases
// (--source-file=*/<method>/<law>.cpp), and doctest exits 0 when its filters match no test case: a renamed or
// emptied file would pass silently. Here a run that executed no test case fails.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>

namespace {

unsigned test_cases_run = 0;

// A doctest listener that records how many test cases passed the filters of the run; it reports nothing.
struct TestCaseCounter : doctest::IReporter
{
    explicit TestCaseCounter(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats& stats) override
    {
        test_cases_run = stats.numTestCasesPassingFilters;
    }
    void test_case_start(const doctest::TestCaseData&) override {}
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

REGISTER_LISTENER("test_case_counter", 1, TestCaseCounter);

} // namespace

int main(int argc, char** argv)
{
    doctest::Context context(argc, argv);
    const int status = context.run();
    if (context.shouldExit() || status != 0) // a query (--help, --list-test-cases) or a failure
        return status;
    if (test_cases_run == 0) {
        std::fprintf(stderr, "verification: the filters matched no test case, so nothing was checked; a test "
                             "that runs nothing fails (was its source file renamed or emptied?)\n");
        return 1;
    }
    return 0;
}
