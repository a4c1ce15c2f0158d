/* Timing of SuiteSparse's sparse direct solvers on a matrix in compressed columns, for
 * bench/src/sparse_direct.f90 (bench/sparse_direct.py): UMFPACK (multifrontal LU) and KLU
 * (left-looking LU after a block triangular form, for circuit-like matrices). For each
 * the shortest wall time of `reps` repetitions of the symbolic analysis (done once per
 * sparsity pattern), the numeric factorisation (once per Newton tangent) and the solve
 * (once per Newton iteration), and the solution of the last. Returns 0 on success. */
#include <suitesparse/klu.h>
#include <suitesparse/umfpack.h>
#include <string.h>
#include <time.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void keep_min(double *best, double t) {
  if (t < *best) *best = t;
}

int rodyn_bench_umfpack(int n, const int *ap, const int *ai, const double *ax,
                        const double *b, double *x, int reps, double *times) {
  times[0] = times[1] = times[2] = 1e300;
  for (int r = 0; r < reps; r++) {
    void *sym = NULL, *num = NULL;
    double t0 = now();
    if (umfpack_di_symbolic(n, n, ap, ai, ax, &sym, NULL, NULL) != UMFPACK_OK) return 1;
    double t1 = now();
    if (umfpack_di_numeric(ap, ai, ax, sym, &num, NULL, NULL) != UMFPACK_OK) return 2;
    double t2 = now();
    if (umfpack_di_solve(UMFPACK_A, ap, ai, ax, x, b, num, NULL, NULL) != UMFPACK_OK)
      return 3;
    double t3 = now();
    umfpack_di_free_numeric(&num);
    umfpack_di_free_symbolic(&sym);
    keep_min(&times[0], t1 - t0);
    keep_min(&times[1], t2 - t1);
    keep_min(&times[2], t3 - t2);
  }
  return 0;
}

int rodyn_bench_klu(int n, const int *ap, const int *ai, const double *ax,
                    const double *b, double *x, int reps, double *times) {
  klu_common c;
  klu_defaults(&c);
  times[0] = times[1] = times[2] = 1e300;
  for (int r = 0; r < reps; r++) {
    double t0 = now();
    klu_symbolic *sym = klu_analyze(n, (int *)ap, (int *)ai, &c);
    if (sym == NULL) return 1;
    double t1 = now();
    klu_numeric *num = klu_factor((int *)ap, (int *)ai, (double *)ax, sym, &c);
    if (num == NULL) return 2;
    double t2 = now();
    memcpy(x, b, (size_t)n * sizeof(double));
    if (!klu_solve(sym, num, n, 1, x, &c)) return 3;
    double t3 = now();
    klu_free_numeric(&num, &c);
    klu_free_symbolic(&sym, &c);
    keep_min(&times[0], t1 - t0);
    keep_min(&times[1], t2 - t1);
    keep_min(&times[2], t3 - t2);
  }
  return 0;
}
