/* Newton's set-up on a large partial-slip system (contactlib.default_method.newton_on_k with
 * overwrite), fused: the equilibration in one pass over the rows, and the in-place scaling
 * with the first A(k) in a second, where numpy makes six passes and two fresh temporaries.
 *
 * A(k) = a0 + k a1, a1 nonzero in the columns [start, start + nb) only (held as a1b). The
 * operations are numpy's, on the same operands in the same order (maxima are exact), so the
 * same bits (tests/test_kernels_fused.py); built with -ffp-contract=off.
 */
#include "../fused_buffers.h"
#include <math.h>

/* the larger of m and v, NaN kept (np.max, np.maximum propagate NaN) */
static inline double nanmax(double m, double v) { return (v > m || v != v) ? v : m; }

/* whether a0 (l0 doubles) and a1b (l1) hold a system of `size` unknowns, a1b's nb columns
 * (set here) at columns start ... start + nb - 1 of A: the check every function here makes */
static int system_ok(Py_ssize_t l0, Py_ssize_t l1, Py_ssize_t size, Py_ssize_t start,
                     Py_ssize_t *nb)
{
    *nb = size > 0 ? l1 / size : 0;
    return l0 == size * size && l1 == size * *nb && start >= 0 && start + *nb <= size;
}

/* equilibrate(a0, a1b, start, k, rs, colmax): rs_i = 1 / max_j |A_ij|,
 * colmax_j = max_i |A_ij| rs_i (default_method._equilibration) */
static PyObject *py_equilibrate(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *o0, *o1, *ors, *ocm;
    Py_ssize_t start, l0 = -1, l1 = -1, lrs = -1, lcm = -1;
    double k;
    bufs_t bs = {.n = 0};
    if (!PyArg_ParseTuple(args, "OOndOO", &o0, &o1, &start, &k, &ors, &ocm))
        return NULL;
    const double *a0 = get(&bs, o0, 0, &l0, "a0"), *a1 = a0 ? get(&bs, o1, 0, &l1, "a1b") : NULL;
    double *rs = a1 ? get(&bs, ors, 1, &lrs, "rs") : NULL;
    double *cm = rs ? get(&bs, ocm, 1, &lcm, "colmax") : NULL;
    Py_ssize_t size = lrs, nb = 0;
    if (cm != NULL && !(system_ok(l0, l1, size, start, &nb) && lcm == size)) {
        PyErr_SetString(PyExc_ValueError, "equilibrate needs a0 (n, n), a1b (n, nb), rs and "
                                          "colmax (n,), 0 <= start <= n - nb");
        cm = NULL;
    }
    if (cm == NULL) {
        release(&bs);
        return NULL;
    }
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t j = 0; j < size; j++)
        cm[j] = 0.0;
    for (Py_ssize_t i = 0; i < size; i++) {
        const double *r0 = a0 + i * size, *r1 = a1 + i * nb;
        double top = -INFINITY, inv;
        for (Py_ssize_t j = 0; j < size; j++) {
            double v = r0[j];
            if (j >= start && j < start + nb)
                v = v + k * r1[j - start];
            top = nanmax(top, fabs(v));
        }
        inv = 1.0 / top;
        rs[i] = inv;
        for (Py_ssize_t j = 0; j < size; j++) {
            double v = r0[j];
            if (j >= start && j < start + nb)
                v = v + k * r1[j - start];
            cm[j] = nanmax(cm[j], fabs(v) * inv);
        }
    }
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

/* scale_form(a0, a1b, start, rs, cs, k, ak): a0 <- (a0 rs_i) cs_j and a1b <- (a1b rs_i)
 * cs_(start + j) in place, and ak = a0 + k a1 of the scaled system (newton_on_k's first
 * iteration) */
static PyObject *py_scale_form(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *o0, *o1, *ors, *ocs, *oak;
    Py_ssize_t start, l0 = -1, l1 = -1, lrs = -1, lcs = -1, lak = -1;
    double k;
    bufs_t bs = {.n = 0};
    if (!PyArg_ParseTuple(args, "OOnOOdO", &o0, &o1, &start, &ors, &ocs, &k, &oak))
        return NULL;
    double *a0 = get(&bs, o0, 1, &l0, "a0"), *a1 = a0 ? get(&bs, o1, 1, &l1, "a1b") : NULL;
    const double *rs = a1 ? get(&bs, ors, 0, &lrs, "rs") : NULL;
    const double *cs = rs ? get(&bs, ocs, 0, &lcs, "cs") : NULL;
    double *ak = cs ? get(&bs, oak, 1, &lak, "ak") : NULL;
    Py_ssize_t size = lrs, nb = 0;
    if (ak != NULL
        && !(system_ok(l0, l1, size, start, &nb) && lcs == size && lak == size * size)) {
        PyErr_SetString(PyExc_ValueError, "scale_form needs a0 and ak (n, n), a1b (n, nb), "
                                          "rs and cs (n,), 0 <= start <= n - nb");
        ak = NULL;
    }
    if (ak == NULL) {
        release(&bs);
        return NULL;
    }
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t i = 0; i < size; i++) {
        double *r0 = a0 + i * size, *r1 = a1 + i * nb, *rk = ak + i * size;
        const double ri = rs[i];
        for (Py_ssize_t j = 0; j < size; j++) {
            double v = r0[j] * ri;
            v = v * cs[j];
            r0[j] = v;
            rk[j] = v;
        }
        for (Py_ssize_t j = 0; j < nb; j++) {
            double v = r1[j] * ri;
            v = v * cs[start + j];
            r1[j] = v;
            rk[start + j] = rk[start + j] + k * v;
        }
    }
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

/* numpy's einsum("ij,j->i", e, y) on one row in long double, double e and y: numpy's loop for
 * long double (einsum_sumprod.c.src, contig_contig_outstride0_two, no SIMD for long double)
 * sums products four at a time, (((ab0 + ab1) + ab2) + ab3) added to the accumulator, the
 * tail one by one; its buffered iterator hands a row over in runs of at most `buf` elements
 * (8192, its fixed NPY_BUFSIZE: np.setbufsize does not change it), each run's sum added to
 * the output element, which starts at 0 */
static long double run_sum(const double *r, const double *y, Py_ssize_t count)
{
    long double accum = 0.0L;
    for (; count >= 4; count -= 4, r += 4, y += 4) {
        const long double ab0 = (long double)r[0] * (long double)y[0];
        const long double ab1 = (long double)r[1] * (long double)y[1];
        const long double ab2 = (long double)r[2] * (long double)y[2];
        const long double ab3 = (long double)r[3] * (long double)y[3];
        accum += ab0 + ab1 + ab2 + ab3;
    }
    for (; count > 0; --count, ++r, ++y)
        accum += (long double)r[0] * (long double)y[0];
    return accum;
}

static long double row_sum(const double *r, const double *y, Py_ssize_t m, Py_ssize_t buf)
{
    long double out = 0.0L;
    for (Py_ssize_t j = 0; j < m; j += buf)
        out = out + run_sum(r + j, y + j, m - j < buf ? m - j : buf);
    return out;
}

/* residual(a0, a1b, start, k, y, rhs, buf, out): out = rhs - (a0 y + k a1b y[start:start+nb])
 * in long double, rounded to double, as default_method._extended_residual's einsum route
 * computes it (the same operations in the same order, so the same bits) */
static PyObject *py_residual(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *o0, *o1, *oy, *orhs, *oout;
    Py_ssize_t start, buf, l0 = -1, l1 = -1, ly = -1, lrhs = -1, lout = -1;
    double k;
    bufs_t bs = {.n = 0};
    if (!PyArg_ParseTuple(args, "OOndOOnO", &o0, &o1, &start, &k, &oy, &orhs, &buf, &oout))
        return NULL;
    const double *a0 = get(&bs, o0, 0, &l0, "a0"), *a1 = a0 ? get(&bs, o1, 0, &l1, "a1b") : NULL;
    const double *y = a1 ? get(&bs, oy, 0, &ly, "y") : NULL;
    const double *rhs = y ? get(&bs, orhs, 0, &lrhs, "rhs") : NULL;
    double *out = rhs ? get(&bs, oout, 1, &lout, "out") : NULL;
    Py_ssize_t size = ly, nb = 0;
    if (out != NULL
        && !(system_ok(l0, l1, size, start, &nb) && lrhs == size && lout == size && buf >= 1)) {
        PyErr_SetString(PyExc_ValueError, "residual needs a0 (n, n), a1b (n, nb), y, rhs and "
                                          "out (n,), 0 <= start <= n - nb, buf >= 1");
        out = NULL;
    }
    if (out == NULL) {
        release(&bs);
        return NULL;
    }
    const long double ke = (long double)k;
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t i = 0; i < size; i++) {
        long double acc = row_sum(a0 + i * size, y, size, buf);
        acc += ke * row_sum(a1 + i * nb, y + start, nb, buf);
        out[i] = (double)((long double)rhs[i] - acc);
    }
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

static PyMethodDef methods[] = {
    {"equilibrate", py_equilibrate, METH_VARARGS,
     "equilibrate(a0, a1b, start, k, rs, colmax): row scales and column maxima of A(k)."},
    {"scale_form", py_scale_form, METH_VARARGS,
     "scale_form(a0, a1b, start, rs, cs, k, ak): the system scaled in place and A(k)."},
    {"residual", py_residual, METH_VARARGS,
     "residual(a0, a1b, start, k, y, rhs, buf, out): rhs - A(k) y in long double."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "solver_fused",
                                    "Fused set-up of Newton's method on k (see "
                                    "contactlib.default_method).",
                                    -1, methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit_solver_fused(void) { return PyModule_Create(&module); }
