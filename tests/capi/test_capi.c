/* librodyn against MoorDyn's C API (docs/capi.md), on MoorDyn's OC3-Hywind lines
 * (tests/decks/good/moordyn/lines.txt: three 902.2 m chains, fairleads Vessel points
 * 4-6 at 70 m depth, 20 segments a line):
 *  1. a missing file gives NULL; counts and IDs as MoorDyn's (9 coupled DOFs, lines and
 *     points from 1, NULL past them); MoorDyn_Step before MoorDyn_Init refused;
 *  2. after MoorDyn_Init the force on fairlead 4 (MoorDyn_Step with dt = 0) is the
 *     grounded elastic catenary's (H, V) (Irvine 1981, the values check_moordyn_file.py
 *     solves), within 2e-3 (MoorDyn's 20 segments);
 *  3. 40 steps of 0.5 s with the fairleads held: the forces stay the static ones to
 *     1e-8 (the statics are the dynamics' rest);
 *  4. the fairleads surged 2 m at 10 s for 20 s: every step succeeds, t advances by
 *     dt, and the force on fairlead 4 (towards its anchor at +x) falls when it moves
 *     towards the anchor (t = 2.5 s) and rises when it moves away (t = 7.5 s);
 *  5. MoorDyn's first API: a missing file gives MOORDYN_UNHANDLED_ERROR, and
 *     MoorDynClose without a system MOORDYN_INVALID_VALUE.
 * Usage: test_capi LINES_TXT. Exit 0 on success. */
#include "MoorDyn.h"
#include "MoorDyn2.h"
#include <math.h>
#include <stdio.h>

static int fails = 0;
#define CHECK(cond, ...)                                                                 \
	do {                                                                                 \
		if (!(cond)) {                                                                   \
			printf("FAIL: " __VA_ARGS__);                                                \
			printf("\n");                                                                \
			fails++;                                                                     \
		}                                                                                \
	} while (0)

int main(int argc, char** argv)
{
	if (argc < 2)
		return 2;
	/* 1. */
	CHECK(MoorDyn_Create("no_such_file.txt") == NULL, "a missing file gives a system");
	MoorDyn s = MoorDyn_Create(argv[1]);
	CHECK(s != NULL, "lines.txt is not read");
	if (!s)
		return 1;
	unsigned int n = 0, nl = 0, np = 0;
	CHECK(MoorDyn_NCoupledDOF(s, &n) == MOORDYN_SUCCESS && n == 9, "coupled DOFs %u", n);
	MoorDyn_GetNumberLines(s, &nl);
	MoorDyn_GetNumberPoints(s, &np);
	CHECK(nl == 3 && np == 6, "%u lines, %u points", nl, np);
	CHECK(MoorDyn_GetLine(s, 0) == NULL && MoorDyn_GetLine(s, 4) == NULL, "line 0 or 4");
	CHECK(MoorDyn_GetPoint(s, 7) == NULL && MoorDyn_GetPoint(s, 6) != NULL, "point 6, 7");
	double x[9], x0[9], xd[9] = { 0 }, f[9], f0[9], t = 0.0, dt = 0.5;
	CHECK(MoorDyn_Step(s, x, xd, f, &t, &dt) == MOORDYN_INVALID_VALUE, "a step before Init");
	for (int i = 0; i < 3; i++)
		MoorDyn_GetPointPos(MoorDyn_GetPoint(s, i + 4), x0 + 3 * i);
	for (int i = 0; i < 9; i++)
		x[i] = x0[i];
	CHECK(fabs(x0[0] - 5.2) + fabs(x0[2] + 70.0) < 1e-12, "point 4 at (%g, %g, %g)",
	      x0[0], x0[1], x0[2]);
	CHECK(MoorDyn_Init(s, x, xd) == MOORDYN_SUCCESS, "MoorDyn_Init");
	/* 2. */
	double zero = 0.0;
	CHECK(MoorDyn_Step(s, x, xd, f0, &t, &zero) == MOORDYN_SUCCESS && t == 0.0, "dt = 0");
	const double h = 736938.8513934187, v = 535727.8495310359;
	double e = hypot(f0[0] - h, -f0[2] - v) / hypot(h, v);
	printf("force on fairlead 4 after Init: (%.3f, %.3f, %.3f) N; catenary (%.3f, 0, %.3f):"
	       " %.2e\n", f0[0], f0[1], f0[2], h, -v, e);
	CHECK(e < 2e-3 && fabs(f0[1]) < 1e-6 * h, "static force %.2e", e);
	/* 3. */
	double worst = 0.0;
	for (int k = 0; k < 40; k++) {
		int c = MoorDyn_Step(s, x, xd, f, &t, &dt);
		CHECK(c == MOORDYN_SUCCESS, "held step %d: %d", k, c);
		for (int i = 0; i < 9; i++)
			worst = fmax(worst, fabs(f[i] - f0[i]) / hypot(h, v));
	}
	printf("40 steps held: t = %g s, largest change of a force %.2e\n", t, worst);
	CHECK(fabs(t - 20.0) < 1e-12 && worst < 1e-8, "held: t %g, change %.2e", t, worst);
	/* 4. */
	const double a = 2.0, w = 2.0 * M_PI / 10.0, t0 = t;
	double fx_toward = 0.0, fx_away = 0.0;
	for (int k = 0; k < 40; k++) {
		double tau = t - t0;
		for (int i = 0; i < 3; i++) {
			x[3 * i] = x0[3 * i] + a * sin(w * tau);
			xd[3 * i] = a * w * cos(w * tau);
		}
		int c = MoorDyn_Step(s, x, xd, f, &t, &dt);
		CHECK(c == MOORDYN_SUCCESS && fabs(t - t0 - 0.5 * (k + 1)) < 1e-9, "surge step %d", k);
		if (k == 4)
			fx_toward = f[0];
		if (k == 14)
			fx_away = f[0];
	}
	printf("surged: Fx on fairlead 4 at 2.5 s %.1f N, at 7.5 s %.1f N (static %.1f N)\n",
	       fx_toward, fx_away, f0[0]);
	CHECK(fx_toward < f0[0] && fx_away > f0[0], "surge forces");
	CHECK(MoorDyn_Close(s) == MOORDYN_SUCCESS, "MoorDyn_Close");
	/* 5. */
	CHECK(MoorDynInit(x, xd, "no_such_file.txt") == MOORDYN_UNHANDLED_ERROR, "MoorDynInit");
	CHECK(MoorDynClose() == MOORDYN_INVALID_VALUE, "MoorDynClose without a system");
	printf(fails ? "%d checks failed\n" : "all checks passed\n", fails);
	return fails ? 1 : 0;
}
