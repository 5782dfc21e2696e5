/* The half-plane strip kernels of contactlib.kernels.strip (_hp_pressure, _hp_shear), fused:
 * the arithmetic in one pass a point, the logarithms by numpy between two passes (this file
 * cannot reproduce numpy's log; log1p is the C library's in both).
 *
 * args() forms the logarithms' arguments, finish() the rest, each with exactly the IEEE
 * operations of the numpy functions in the same order, so the same bits (built with
 * -ffp-contract=off; tests/test_kernels_fused.py compares both routes). Arguments are
 * contiguous float64 buffers of one length.
 */
#include "../fused_buffers.h"
#include <math.h>

static const char *const ARG_NAMES[] = {"argument 1", "argument 2", "argument 3", "argument 4",
                                        "argument 5", "argument 6", "argument 7"};

/* pressure: a1 = a + s (for log), a2 = 2 m / |a - s| (for log1p) */
CLONES static void pressure_args(const double *x, const double *s, double *a1, double *a2,
                                 Py_ssize_t k)
{
    for (Py_ssize_t i = 0; i < k; i++) {
        double a = fabs(x[i]), ad = fabs(a - s[i]), m = a <= s[i] ? a : s[i];
        a1[i] = a + s[i];
        a2[i] = (2.0 * m) / ad;
    }
}

/* shear: a2 = 2 m / |a - s| (log1p), a3 = (a + s)|a - s| / a^2 (log), a4 = -(s/a)^2 (log1p) */
CLONES static void shear_args(const double *x, const double *s, double *a2, double *a3,
                              double *a4, Py_ssize_t k)
{
    for (Py_ssize_t i = 0; i < k; i++) {
        double a = fabs(x[i]), ad = fabs(a - s[i]), m = a <= s[i] ? a : s[i], r;
        a2[i] = (2.0 * m) / ad;
        a3[i] = ((a + s[i]) * ad) / (a * a);
        r = s[i] / a;
        r = r * r;
        a4[i] = -r;
    }
}

/* pressure from lp = ln(a + s), q = ln((a + s)/|a - s|) */
CLONES static void pressure_finish(const double *x, const double *s, const double *lp,
                                   const double *q, double b, double two_pi, double *w,
                                   double *u, double *du, Py_ssize_t k)
{
    const double mb2 = -2.0 * b, mb = -b;
    for (Py_ssize_t i = 0; i < k; i++) {
        double a = fabs(x[i]), d = a - s[i], m = a <= s[i] ? a : s[i], v;
        v = 1.0 - lp[i];
        v = v * (2.0 * s[i]);
        if (fabs(d) != 0.0) /* at the edge (a - s) ln|a - s| -> 0 */
            v = v - d * q[i];
        w[i] = v * two_pi;
        u[i] = copysign(m, x[i]) * mb2;
        v = (double)(a < s[i]);
        v = v + (double)(a <= s[i]);
        du[i] = v * mb;
    }
}

/* shear from q = ln((a + s)/|a - s|), l1 = ln|1 - s^2/x^2| */
CLONES static void shear_finish(const double *x, const double *s, const double *q,
                                const double *l1, double b, double two_pi, double ln4,
                                double *w, double *u, double *du, Py_ssize_t k)
{
    const double mb2 = -2.0 * b;
    for (Py_ssize_t i = 0; i < k; i++) {
        double a = fabs(x[i]), ad = fabs(a - s[i]), g, t;
        if (a == 0.0)
            g = 0.0; /* removable points: g(0) = 0, g(s) = 2 s ln 2 */
        else if (ad == 0.0)
            g = ln4 * s[i];
        else {
            g = a * l1[i];
            g = g + s[i] * q[i];
        }
        u[i] = copysign(g, x[i]) * two_pi;
        du[i] = l1[i] * two_pi;
        t = s[i] - a;
        t = t >= 0.0 ? t : 0.0;
        w[i] = t * mb2;
    }
}

/* args(kind, x, s, a1/a2, a2/a3, [a4]): see pressure_args, shear_args */
static PyObject *py_args(PyObject *Py_UNUSED(self), PyObject *args)
{
    int shear;
    PyObject *o[5] = {NULL};
    if (!PyArg_ParseTuple(args, "pOOOO|O", &shear, &o[0], &o[1], &o[2], &o[3], &o[4]))
        return NULL;
    int count = shear ? 5 : 4;
    if (shear && o[4] == NULL) {
        PyErr_SetString(PyExc_TypeError, "the shear needs three argument arrays");
        return NULL;
    }
    bufs_t bs = {.n = 0};
    double *p[5];
    Py_ssize_t k;
    if (get_vectors(&bs, o, count, count - 2, p, &k, ARG_NAMES) != 0) {
        release(&bs);
        return NULL;
    }
    Py_BEGIN_ALLOW_THREADS
    if (shear)
        shear_args(p[0], p[1], p[2], p[3], p[4], k);
    else
        pressure_args(p[0], p[1], p[2], p[3], k);
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

/* finish(kind, x, s, l_a, l_b, b, two_pi, ln4, w, u, du): pressure (l_a = lp, l_b = q) or
 * shear (l_a = q, l_b = l1) */
static PyObject *py_finish(PyObject *Py_UNUSED(self), PyObject *args)
{
    int shear;
    double b, two_pi, ln4;
    PyObject *o[7];
    if (!PyArg_ParseTuple(args, "pOOOOdddOOO", &shear, &o[0], &o[1], &o[2], &o[3], &b, &two_pi,
                          &ln4, &o[4], &o[5], &o[6]))
        return NULL;
    bufs_t bs = {.n = 0};
    double *p[7];
    Py_ssize_t k;
    if (get_vectors(&bs, o, 7, 3, p, &k, ARG_NAMES) != 0) {
        release(&bs);
        return NULL;
    }
    Py_BEGIN_ALLOW_THREADS
    if (shear)
        shear_finish(p[0], p[1], p[2], p[3], b, two_pi, ln4, p[4], p[5], p[6], k);
    else
        pressure_finish(p[0], p[1], p[2], p[3], b, two_pi, p[4], p[5], p[6], k);
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

static PyMethodDef methods[] = {
    {"args", py_args, METH_VARARGS,
     "args(shear, x, s, ...): the logarithms' arguments of the half-plane strip kernels."},
    {"finish", py_finish, METH_VARARGS,
     "finish(shear, x, s, l_a, l_b, b, two_pi, ln4, w, u, du): the half-plane strip kernels "
     "from their logarithms."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "strip_fused",
                                    "Fused half-plane strip kernels (see "
                                    "contactlib.kernels.strip).",
                                    -1, methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit_strip_fused(void) { return PyModule_Create(&module); }
