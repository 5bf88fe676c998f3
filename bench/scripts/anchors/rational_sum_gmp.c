/* rational-sum in C on GMP's mpq_t: the same computation as rational_sum.py (see there), without an
 * interpreter, so that the cost of the Python layer of the gmpy2 and python-flint anchors is
 * visible. Built and run by rational_sum_gmp.py against the libgmp that gmpy2 bundles; the few GMP
 * declarations it needs are written out below because the wheel ships no gmp.h (the layouts are
 * GMP's documented ABI: mpz = {int alloc; int size; limb *d}, mpq = {mpz num; mpz den}).
 *
 * Usage: rational_sum_gmp MODE N      (MODE: seq | eval | tree)
 * Prints one JSON line with seconds, cpu_seconds and the check values of rational_sum.py. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct { int alloc; int size; unsigned long *d; } mpz_struct;
typedef struct { mpz_struct num; mpz_struct den; } mpq_struct;
typedef mpq_struct mpq_t[1];

extern void __gmpq_init(mpq_struct *);
extern void __gmpq_clear(mpq_struct *);
extern void __gmpq_set(mpq_struct *, const mpq_struct *);
extern void __gmpq_set_si(mpq_struct *, long, unsigned long);
extern void __gmpq_canonicalize(mpq_struct *);
extern void __gmpq_add(mpq_struct *, const mpq_struct *, const mpq_struct *);
extern void __gmpq_sub(mpq_struct *, const mpq_struct *, const mpq_struct *);
extern void __gmpq_mul(mpq_struct *, const mpq_struct *, const mpq_struct *);
extern void __gmpq_div(mpq_struct *, const mpq_struct *, const mpq_struct *);
extern double __gmpq_get_d(const mpq_struct *);
extern char *__gmpz_get_str(char *, int, const mpz_struct *);
extern unsigned long __gmpz_fdiv_ui(const mpz_struct *, unsigned long);
extern const char *const __gmp_version;

static double now(clockid_t c) {
    struct timespec ts;
    clock_gettime(c, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void set_q(mpq_struct *x, long p, unsigned long q) {
    __gmpq_set_si(x, p, q);
    __gmpq_canonicalize(x);
}

static mpq_t a, b, r, d, e, f, R2, cb, sb, cg, sg, one, two, fifty, sgsb, cgsb, sgcb, cgcb;
static mpq_t T2, den, ct, st, X, Y, u, v, w, A, B, t, t1;

/* res = disc(T), the same operations as rational_sum.py's disc */
static void disc(mpq_struct *res, const mpq_struct *T) {
    __gmpq_mul(T2, T, T);
    __gmpq_add(den, one, T2);
    __gmpq_sub(t, one, T2);
    __gmpq_div(ct, t, den);
    __gmpq_mul(t, two, T);
    __gmpq_div(st, t, den);
    __gmpq_mul(t, r, ct); __gmpq_add(X, a, t);
    __gmpq_mul(t, r, st); __gmpq_add(Y, b, t);
    __gmpq_mul(t, cb, X); __gmpq_sub(u, t, d);
    __gmpq_mul(t, cg, Y); __gmpq_mul(t1, sgsb, X); __gmpq_sub(v, t, t1); __gmpq_sub(v, v, e);
    __gmpq_mul(t, sg, Y); __gmpq_mul(t1, cgsb, X); __gmpq_add(w, t, t1); __gmpq_add(w, w, f);
    __gmpq_mul(A, sb, u); __gmpq_mul(t, sgcb, v); __gmpq_add(A, A, t);
    __gmpq_mul(t, cgcb, w); __gmpq_sub(A, A, t);
    __gmpq_mul(B, u, u); __gmpq_mul(t, v, v); __gmpq_add(B, B, t);
    __gmpq_mul(t, w, w); __gmpq_add(B, B, t); __gmpq_sub(B, B, R2);
    __gmpq_mul(t, A, A); __gmpq_sub(res, t, B);
}

static int sign(const mpq_struct *x) { return x->num.size < 0 ? -1 : x->num.size > 0; }

static size_t digits(const mpz_struct *z) {
    char *s = __gmpz_get_str(NULL, 10, z);
    size_t n = strlen(s) - (s[0] == '-');
    free(s); /* GMP's default allocator is malloc */
    return n;
}

int main(int argc, char **argv) {
    if (argc != 3) { fprintf(stderr, "usage: rational_sum_gmp seq|eval|tree N\n"); return 2; }
    const char *mode = argv[1];
    long N = atol(argv[2]);
    if (strcmp(mode, "seq") && strcmp(mode, "eval") && strcmp(mode, "tree")) {
        fprintf(stderr, "unknown mode %s\n", mode); return 2;
    }
    mpq_struct *all[] = {a, b, r, d, e, f, R2, cb, sb, cg, sg, one, two, fifty, sgsb, cgsb, sgcb,
                         cgcb, T2, den, ct, st, X, Y, u, v, w, A, B, t, t1};
    for (size_t i = 0; i < sizeof all / sizeof *all; i++) __gmpq_init(all[i]);
    set_q(a, 1, 3); set_q(b, -2, 7); set_q(r, 5, 1); set_q(d, 1, 1); set_q(e, 2, 1); set_q(f, 4, 1);
    set_q(R2, 25, 1); set_q(cb, 3, 5); set_q(sb, 4, 5); set_q(cg, 5, 13); set_q(sg, -12, 13);
    set_q(one, 1, 1); set_q(two, 2, 1); set_q(fifty, 50, 1);
    /* the products of constants, as Python evaluates sg * sb * X left to right: (sg sb) X */
    __gmpq_mul(sgsb, sg, sb); __gmpq_mul(cgsb, cg, sb); __gmpq_mul(sgcb, sg, cb); __gmpq_mul(cgcb, cg, cb);

    mpq_t T, D, s;
    __gmpq_init(T); __gmpq_init(D); __gmpq_init(s);
    mpq_struct *vals = NULL;
    long count = 0;
    double w0 = now(CLOCK_MONOTONIC), c0 = now(CLOCK_PROCESS_CPUTIME_ID);
    if (!strcmp(mode, "tree")) {
        vals = malloc(sizeof(mpq_struct) * (size_t)(N > 0 ? N : 1));
        if (!vals) { fprintf(stderr, "out of memory\n"); return 1; }
    }
    for (long k = 0; k < N; k++) {
        set_q(T, k, 1000);
        __gmpq_sub(T, T, fifty);
        disc(D, T);
        if (sign(D) >= 0) count++;
        if (!strcmp(mode, "seq")) __gmpq_add(s, s, D);
        else if (vals) { __gmpq_init(&vals[k]); __gmpq_set(&vals[k], D); }
    }
    if (vals) {
        long n = N;
        while (n > 1) {
            long m = 0;
            for (long i = 0; i + 1 < n; i += 2) {
                __gmpq_add(&vals[m], &vals[i], &vals[i + 1]);
                m++;
            }
            if (n % 2) { __gmpq_set(&vals[m], &vals[n - 1]); m++; }
            for (long i = m; i < n; i++) __gmpq_clear(&vals[i]);
            n = m;
        }
        if (N > 0) __gmpq_set(s, &vals[0]);
    }
    double seconds = now(CLOCK_MONOTONIC) - w0, cpu = now(CLOCK_PROCESS_CPUTIME_ID) - c0;
    printf("{\"tool\": \"gmp-c\", \"version\": \"GMP %s\", \"mode\": \"%s\", \"N\": %ld, "
           "\"seconds\": %.9f, \"cpu_seconds\": %.9f, \"threads\": 1, \"count_nonneg\": %ld",
           __gmp_version, mode, N, seconds, cpu, count);
    if (strcmp(mode, "eval")) {
        printf(", \"sum_num_digits\": %zu, \"sum_den_digits\": %zu, \"sum_num_mod_p\": %lu, "
               "\"sum_den_mod_p\": %lu, \"sum_approx\": %.17g",
               digits(&s->num), digits(&s->den), __gmpz_fdiv_ui(&s->num, 1000000007UL),
               __gmpz_fdiv_ui(&s->den, 1000000007UL), __gmpq_get_d(s));
    }
    printf("}\n");
    return 0;
}
