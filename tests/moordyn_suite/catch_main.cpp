// The main of the Catch2 stand-in (catch2/catch_test_macros.hpp): every registered test
// case run in turn, or those named on the command line (as Catch2 takes test names); the
// exit status is the number of test cases that failed, or 1 when a name matches none.
#include "catch2/catch_test_macros.hpp"
#include <set>
#include <string>

int
main(int argc, char** argv)
{
	std::set<std::string> wanted(argv + 1, argv + argc);
	const bool all = wanted.empty();
	int failed = 0;
	for (auto& tc : rodyn_catch::registry()) {
		if (!all && !wanted.erase(tc.name))
			continue;
		int before = rodyn_catch::check_failures();
		bool ok = true;
		try {
			tc.run();
		} catch (const rodyn_catch::RequireFailure&) {
			ok = false;
		} catch (const std::exception& e) {
			std::cerr << tc.name << ": exception: " << e.what() << "\n";
			ok = false;
		}
		if (rodyn_catch::check_failures() != before)
			ok = false;
		std::cout << (ok ? "passed: " : "FAILED: ") << tc.name << "\n";
		failed += ok ? 0 : 1;
	}
	for (auto& name : wanted) {
		std::cerr << "no test case named \"" << name << "\"\n";
		failed += 1;
	}
	return failed;
}
