/* The disc kernels of contactlib.kernels.disc, fused: one pass a point instead of one numpy
 * pass an operation.
 *
 * Every function here performs, for each point, exactly the IEEE operations of the numpy
 * chunk functions of disc.py (_params, _pressure_chunk, _shear_chunk, ...), in the same
 * order and with the same operands: the results are the same bits (built without
 * contraction into fused multiply-adds, -ffp-contract=off; tests/test_kernels_fused.py
 * compares both routes bit for bit). The logarithm is not taken here: the caller passes
 * lg = log(max(m1, tiny)) computed by numpy (whose log this file cannot reproduce), from
 * the m1 that m1() writes.
 *
 * Arguments are contiguous float64 buffers of one length k. Coefficient stacks are
 * (degree + 1) x rows, highest degree first, rows (P, R) of each fitted function, as
 * disc._stack builds them.
 */
#include "../fused_buffers.h"
#include <math.h>

#define NC 11 /* coefficients of each polynomial (degree 10) */

#define INLINE static inline __attribute__((always_inline))

typedef struct {
    double ra, q, m1;
    int inside;
} params_t;

INLINE params_t params(double r, double s)
{
    params_t p;
    double big, small;
    p.ra = fabs(r);
    p.inside = p.ra <= s;
    big = p.ra >= s ? p.ra : s;   /* np.maximum / np.minimum of finite values */
    small = p.ra <= s ? p.ra : s;
    p.q = small / big;
    p.m1 = big - small;
    p.m1 = p.m1 / big;
    p.m1 = p.m1 * (p.q + 1.0);
    return p;
}

#define BLOCK 64 /* points a block: the polynomials run across the block (vectorized) */

/* out[i] = P + ln(m1) R of function f (rows 2f, 2f + 1 of `stack`) for n points: the
 * operations of disc._log_form point by point (c0 x + c1, then (.) x + cj; R ln(m1) + P) */
INLINE void uniform_log_form(const double *stack, int rows, int f, int n, const double *m1,
                             const double *lg, double *out)
{
    double p[BLOCK], r[BLOCK];
    const int rp = 2 * f, rr = 2 * f + 1;
    const double p0 = stack[rp], r0 = stack[rr], p1 = stack[rows + rp], r1 = stack[rows + rr];
    for (int i = 0; i < n; i++) {
        p[i] = p0 * m1[i];
        r[i] = r0 * m1[i];
        p[i] = p[i] + p1;
        r[i] = r[i] + r1;
    }
    for (int j = 2; j < NC; j++) {
        const double a = stack[j * rows + rp], b = stack[j * rows + rr];
        for (int i = 0; i < n; i++) {
            p[i] = p[i] * m1[i];
            r[i] = r[i] * m1[i];
            p[i] = p[i] + a;
            r[i] = r[i] + b;
        }
    }
    for (int i = 0; i < n; i++) {
        r[i] = r[i] * lg[i];
        out[i] = p[i] + r[i];
    }
}

/* the same for a block whose points lie inside (stack sin_) or outside (sout) the disc:
 * each run of points on one side by its own stack */
INLINE void block_log_form(const double *sin_, const double *sout, int rows, int f, int n,
                           const double *m1, const double *lg, const int *inside, double *out)
{
    int a = 0;
    while (a < n) {
        int e = a + 1;
        while (e < n && inside[e] == inside[a])
            e++;
        uniform_log_form(inside[a] ? sin_ : sout, rows, f, e - a, m1 + a, lg + a, out + a);
        a = e;
    }
}


/* m1(r, s, out): 1 - q^2 as disc._params forms it */
static PyObject *py_m1(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *or, *os, *oo;
    bufs_t bs = {.n = 0};
    Py_ssize_t k = -1;
    if (!PyArg_ParseTuple(args, "OOO", &or, &os, &oo))
        return NULL;
    double *r = get(&bs, or, 0, &k, "r"), *s = r ? get(&bs, os, 0, &k, "s") : NULL;
    double *out = s ? get(&bs, oo, 1, &k, "out") : NULL;
    if (out == NULL) {
        release(&bs);
        return NULL;
    }
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t i = 0; i < k; i++)
        out[i] = params(r[i], s[i]).m1;
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

/* params() of the n points of a block, into arrays */
INLINE void block_params(const double *r, const double *s, int n, double *m1, double *q,
                         double *ra, int *inside)
{
    for (int i = 0; i < n; i++) {
        params_t p = params(r[i], s[i]);
        m1[i] = p.m1, q[i] = p.q, ra[i] = p.ra, inside[i] = p.inside;
    }
}

CLONES static void pressure_work(const double *r, const double *s, const double *lg, double b,
                                 double c_w, const double *sin_, const double *sout, double *w,
                                 double *u, double *du, Py_ssize_t k)
{
    double m1[BLOCK], q[BLOCK], ra[BLOCK], v[BLOCK];
    int inside[BLOCK];
    for (Py_ssize_t i0 = 0; i0 < k; i0 += BLOCK) {
        int n = k - i0 < BLOCK ? (int)(k - i0) : BLOCK;
        const double *rb = r + i0, *sb = s + i0;
        block_params(rb, sb, n, m1, q, ra, inside);
        block_log_form(sin_, sout, 2, 0, n, m1, lg + i0, inside, v);
        for (int i = 0; i < n; i++) {
            double x = v[i];
            u[i0 + i] = (sb[i] * q[i]) * (-b);
            if (inside[i]) {
                x = x * sb[i];
                w[i0 + i] = x * c_w;
                du[i0 + i] = -b;
            } else {
                x = x * q[i];
                x = x * q[i];
                x = x * ra[i];
                w[i0 + i] = x * c_w;
                du[i0 + i] = (q[i] * q[i]) * b;
            }
        }
    }
}

/* the buffers of a kernel call: r, s, lg (k values each), the stacks ((NC, rows) each), and
 * w, u, du (k values each, written); 0 on success, -1 with an exception set (and released) */
typedef struct {
    double *r, *s, *lg, *sin_, *sout, *w, *u, *du;
    Py_ssize_t k;
} kargs_t;

static int kernel_args(bufs_t *bs, PyObject *const obj[8], int rows, kargs_t *a)
{
    static const char *names[8] = {"r", "s", "lg", "stack_in", "stack_out", "w", "u", "du"};
    double **dest[8] = {&a->r, &a->s, &a->lg, &a->sin_, &a->sout, &a->w, &a->u, &a->du};
    Py_ssize_t k = -1;
    for (int i = 0; i < 8; i++) {
        Py_ssize_t len = (i == 3 || i == 4) ? rows * NC : -1;
        *dest[i] = get(bs, obj[i], i >= 5, (i == 3 || i == 4) ? &len : &k, names[i]);
        if (*dest[i] == NULL) {
            release(bs);
            return -1;
        }
    }
    a->k = k;
    return 0;
}

/* pressure(r, s, lg, b, c_w, stack_in, stack_out, w, u, du): disc._pressure_chunk */
static PyObject *py_pressure(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *o[8];
    double b, c_w;
    bufs_t bs = {.n = 0};
    kargs_t a;
    if (!PyArg_ParseTuple(args, "OOOddOOOOO", &o[0], &o[1], &o[2], &b, &c_w, &o[3], &o[4], &o[5],
                          &o[6], &o[7]) || kernel_args(&bs, o, 2, &a) != 0)
        return NULL;
    Py_BEGIN_ALLOW_THREADS
    pressure_work(a.r, a.s, a.lg, b, c_w, a.sin_, a.sout, a.w, a.u, a.du, a.k);
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

CLONES static void shear_work(const double *r, const double *s, const double *lg, double b,
                              double c_sh, const double *sin_, const double *sout, double *w,
                              double *u, double *du, Py_ssize_t k, int with_du)
{
    const int rows = with_du ? 4 : 2;
    const double c2 = -2.0 * c_sh;
    double m1[BLOCK], q[BLOCK], ra[BLOCK], v0[BLOCK], v1[BLOCK];
    int inside[BLOCK];
    for (Py_ssize_t i0 = 0; i0 < k; i0 += BLOCK) {
        int n = k - i0 < BLOCK ? (int)(k - i0) : BLOCK;
        const double *rb = r + i0, *sb = s + i0;
        block_params(rb, sb, n, m1, q, ra, inside);
        block_log_form(sin_, sout, rows, 0, n, m1, lg + i0, inside, v0);
        if (with_du)
            block_log_form(sin_, sout, rows, 1, n, m1, lg + i0, inside, v1);
        for (int i = 0; i < n; i++) {
            double ww = ra[i] * ra[i], cs, x;
            ww = ww - sb[i] * sb[i];
            ww = ww <= 0.0 ? ww : 0.0;
            w[i0 + i] = ww * b;
            cs = sb[i] * c_sh;
            if (inside[i]) {
                if (with_du)
                    du[i0 + i] = v1[i] * cs;
                x = v0[i] * cs;
                u[i0 + i] = x * ra[i];
            } else {
                double mq = q[i] * q[i];
                x = v0[i] * mq;
                x = x * cs;
                u[i0 + i] = x * sb[i];
                if (with_du) {
                    mq = mq * mq;
                    x = v1[i] * mq;
                    x = x * ra[i];
                    du[i0 + i] = x * c2;
                }
            }
            if (!with_du)
                du[i0 + i] = NAN;
            else if (m1[i] == 0.0)
                du[i0 + i] = -INFINITY;
        }
    }
}

/* shear(r, s, lg, b, c_shear, stack_in, stack_out, w, u, du, with_du): disc._shear_chunk;
 * the stacks have 4 rows (g1, gd1 / h1, hd2), 2 without du (g1 / h1) */
static PyObject *py_shear(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *o[8];
    double b, c_sh;
    int with_du;
    bufs_t bs = {.n = 0};
    kargs_t a;
    if (!PyArg_ParseTuple(args, "OOOddOOOOOp", &o[0], &o[1], &o[2], &b, &c_sh, &o[3], &o[4],
                          &o[5], &o[6], &o[7], &with_du)
        || kernel_args(&bs, o, with_du ? 4 : 2, &a) != 0)
        return NULL;
    Py_BEGIN_ALLOW_THREADS
    shear_work(a.r, a.s, a.lg, b, c_sh, a.sin_, a.sout, a.w, a.u, a.du, a.k, with_du);
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

/* dw/dr of the unit pressure disc (disc._dwdr_pressure): m1 of its E(1 - m1) - K(1 - m1)
 * (no |t|: t >= 0 there), then E - K = P(m1) - ln(m1) Q(m1) and the factor (4/pi)(s/t
 * inside, s at t = 0 inside, 1 outside), the numpy route's operations */
CLONES static void ell_m1_work(const double *t, const double *s, double *m1, Py_ssize_t k)
{
    for (Py_ssize_t i = 0; i < k; i++) {
        double big = t[i] >= s[i] ? t[i] : s[i], small = t[i] <= s[i] ? t[i] : s[i];
        double q = small / big, m = big - small;
        m = m / big;
        q = q + 1.0;
        m1[i] = m * q;
    }
}

CLONES static void dwdr_work(const double *t, const double *s, const double *m1,
                             const double *lg, const double *stack, double c_w, double *diff,
                             double *fac, Py_ssize_t k)
{
    for (Py_ssize_t i0 = 0; i0 < k; i0 += BLOCK) {
        int n = k - i0 < BLOCK ? (int)(k - i0) : BLOCK;
        double p[BLOCK], q[BLOCK];
        const double *x = m1 + i0;
        for (int i = 0; i < n; i++) {
            p[i] = stack[0] * x[i];
            q[i] = stack[1] * x[i];
            p[i] = p[i] + stack[2];
            q[i] = q[i] + stack[3];
        }
        for (int j = 2; j < NC; j++) {
            const double a = stack[2 * j], b = stack[2 * j + 1];
            for (int i = 0; i < n; i++) {
                p[i] = p[i] * x[i];
                q[i] = q[i] * x[i];
                p[i] = p[i] + a;
                q[i] = q[i] + b;
            }
        }
        for (int i = 0; i < n; i++) {
            double l = lg[i0 + i] * q[i];
            diff[i0 + i] = p[i] - l;
        }
    }
    for (Py_ssize_t i = 0; i < k; i++) {
        double f = 1.0;
        if (t[i] < s[i])
            f = t[i] > 0.0 ? s[i] / t[i] : s[i];
        fac[i] = f * c_w;
    }
}

/* ell_m1(t, s, out) */
static PyObject *py_ell_m1(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *o[3];
    bufs_t bs = {.n = 0};
    Py_ssize_t k = -1;
    if (!PyArg_ParseTuple(args, "OOO", &o[0], &o[1], &o[2]))
        return NULL;
    double *t = get(&bs, o[0], 0, &k, "t"), *s = t ? get(&bs, o[1], 0, &k, "s") : NULL;
    double *out = s ? get(&bs, o[2], 1, &k, "out") : NULL;
    if (out == NULL) {
        release(&bs);
        return NULL;
    }
    Py_BEGIN_ALLOW_THREADS
    ell_m1_work(t, s, out, k);
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

/* dwdr(t, s, m1, lg, stack, c_w, diff, fac): stack (11, 2) the rows (P, Q) of E - K */
static PyObject *py_dwdr(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *o[7];
    double c_w;
    bufs_t bs = {.n = 0};
    Py_ssize_t k = -1, ks = 2 * NC;
    if (!PyArg_ParseTuple(args, "OOOOOdOO", &o[0], &o[1], &o[2], &o[3], &o[4], &c_w, &o[5],
                          &o[6]))
        return NULL;
    static const char *names[] = {"t", "s", "m1", "lg", "stack", "diff", "fac"};
    double *p[7];
    for (int i = 0; i < 7; i++) {
        p[i] = get(&bs, o[i], i >= 5, i == 4 ? &ks : &k, names[i]);
        if (p[i] == NULL) {
            release(&bs);
            return NULL;
        }
    }
    Py_BEGIN_ALLOW_THREADS
    dwdr_work(p[0], p[1], p[2], p[3], p[4], c_w, p[5], p[6], k);
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

static PyMethodDef methods[] = {
    {"m1", py_m1, METH_VARARGS, "m1(r, s, out): 1 - q^2 of the disc kernels, in out."},
    {"ell_m1", py_ell_m1, METH_VARARGS, "ell_m1(t, s, out): m1 of dw/dr of the pressure."},
    {"dwdr", py_dwdr, METH_VARARGS,
     "dwdr(t, s, m1, lg, stack, c_w, diff, fac): E - K and the factor of dw/dr of the "
     "pressure."},
    {"pressure", py_pressure, METH_VARARGS,
     "pressure(r, s, lg, b, c_w, stack_in, stack_out, w, u, du): the uniform pressure's "
     "kernels."},
    {"shear", py_shear, METH_VARARGS,
     "shear(r, s, lg, b, c_shear, stack_in, stack_out, w, u, du, with_du): the linear "
     "shear's kernels."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "disc_fused",
                                    "Fused disc kernels (see contactlib.kernels.disc).", -1,
                                    methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit_disc_fused(void) { return PyModule_Create(&module); }
