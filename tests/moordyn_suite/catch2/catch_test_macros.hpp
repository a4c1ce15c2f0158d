// A stand-in for the part of Catch2 v3's catch2/catch_test_macros.hpp that MoorDyn's
// tests use (TEST_CASE, REQUIRE, CHECK, INFO), for building them where Catch2 v3 is not
// installed (Debian 12 ships Catch2 2.13, whose header has another name). Each TEST_CASE
// registers itself; a REQUIRE that fails ends its test case, a CHECK that fails marks
// it failed; catch_main.cpp runs them all and returns the number that failed. Written
// for rodyn's tests/moordyn_suite/ (README.md); not Catch2's code.
#ifndef RODYN_CATCH_SHIM_HPP
#define RODYN_CATCH_SHIM_HPP

#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace rodyn_catch {

struct TestCase
{
	std::string name;
	std::function<void()> run;
};

inline std::vector<TestCase>&
registry()
{
	static std::vector<TestCase> cases;
	return cases;
}

inline std::ostringstream&
info()
{
	static std::ostringstream messages;
	return messages;
}

inline int&
check_failures()
{
	static int n = 0;
	return n;
}

struct Registrar
{
	Registrar(const char* name, std::function<void()> run)
	{
		registry().push_back({ name, run });
	}
	Registrar(const char* name, const char*, std::function<void()> run)
	{
		registry().push_back({ name, run });
	}
};

struct RequireFailure
{};

inline void
report(const char* macro, const char* expr, const char* file, int line)
{
	std::cerr << file << ":" << line << ": FAILED: " << macro << "(" << expr << ")\n";
	if (!info().str().empty())
		std::cerr << "  with: " << info().str() << "\n";
}

} // namespace rodyn_catch

#define RODYN_CATCH_CAT2(a, b) a##b
#define RODYN_CATCH_CAT(a, b) RODYN_CATCH_CAT2(a, b)
#define RODYN_CATCH_TEST(fn, ...)                                                        \
	static void fn();                                                                    \
	static rodyn_catch::Registrar RODYN_CATCH_CAT(fn, _reg)(__VA_ARGS__, fn);            \
	static void fn()
#define TEST_CASE(...) RODYN_CATCH_TEST(RODYN_CATCH_CAT(rodyn_test_, __LINE__), __VA_ARGS__)

#define REQUIRE(...)                                                                     \
	do {                                                                                 \
		if (!(__VA_ARGS__)) {                                                            \
			rodyn_catch::report("REQUIRE", #__VA_ARGS__, __FILE__, __LINE__);            \
			throw rodyn_catch::RequireFailure();                                         \
		}                                                                                \
	} while (0)

#define CHECK(...)                                                                       \
	do {                                                                                 \
		if (!(__VA_ARGS__)) {                                                            \
			rodyn_catch::report("CHECK", #__VA_ARGS__, __FILE__, __LINE__);              \
			rodyn_catch::check_failures()++;                                             \
		}                                                                                \
	} while (0)

#define INFO(msg)                                                                        \
	do {                                                                                 \
		rodyn_catch::info().str("");                                                     \
		rodyn_catch::info() << msg;                                                      \
	} while (0)

#endif
