// The main of the Catch2 stand-in (catch2/catch_test_macros.hpp): every registered test
// case run in turn; the exit status is the number of test cases that failed.
#include "catch2/catch_test_macros.hpp"

int
main(int, char**)
{
	int failed = 0;
	for (auto& tc : rodyn_catch::registry()) {
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
	return failed;
}
