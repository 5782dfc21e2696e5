/* Two steps of building nodal operators, fused: one pass over each row where numpy makes
 * several. Both are the numpy routes' operations on the same operands in the same order, so
 * the same bits (tests/test_kernels_fused.py); built with -ffp-contract=off.
 *
 * difference: contactlib.discretization.influence.apply_difference, element integrals -> nodal operators
 * (numpy: scale, subtract, negate).
 * For each row: s_l = g_l / h_l, then out_0 = s_0, out_l = s_l - s_{l-1}, out_N = -s_{N-1}:
 * the numpy route's operations on the same operands, so the same bits
 * (tests/test_kernels_fused.py). `g` may be the first N columns of `out` (the operator built
 * in place): a row's g_l is read before out_l is written, and out_l is never read again.
 */
#include "../fused_buffers.h"
#include <math.h>

/* restrict: contactlib.discretization.operators.restrict_nested, the fine columns of rows combined into the
 * coarse ones, out_j = (even_j + odd_j left_j) + odd_{j-1} right_{j-1} (numpy: copy, two
 * products, two shifted additions). */

/* difference(g, h, out): g (rows, N), h (N,) element lengths, out (rows, N + 1) */
static PyObject *py_difference(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *og, *oh, *oo;
    bufs_t bs = {.n = 0};
    Py_ssize_t rows, n, sg, rows_o, n1, so, nh = -1;
    if (!PyArg_ParseTuple(args, "OOO", &og, &oh, &oo))
        return NULL;
    const double *g = get_matrix(&bs, og, 0, &rows, &n, &sg, "g");
    double *out = g ? get_matrix(&bs, oo, 1, &rows_o, &n1, &so, "out") : NULL;
    const double *h = out ? get(&bs, oh, 0, &nh, "h") : NULL;
    if (h != NULL && (nh != n || rows_o != rows || n1 != n + 1 || n < 1)) {
        PyErr_SetString(PyExc_ValueError, "difference needs g (rows, N), h (N,) float64 and "
                                          "out (rows, N + 1), N >= 1");
        h = NULL;
    }
    if (h == NULL) {
        release(&bs);
        return NULL;
    }
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t i = 0; i < rows; i++) {
        const double *gi = g + i * sg;
        double *oi = out + i * so;
        double prev = gi[0] / h[0];
        oi[0] = prev;
        for (Py_ssize_t l = 1; l < n; l++) {
            double cur = gi[l] / h[l];
            oi[l] = cur - prev;
            prev = cur;
        }
        oi[n] = -prev;
    }
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

/* restrict(rows, left, right, out): rows (R, 2 Nc + 1), left and right (Nc,), out (R, Nc + 1) */
static PyObject *py_restrict(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *orows, *ol, *orr, *oo;
    bufs_t bs = {.n = 0};
    Py_ssize_t rows, cols, sr, rows_o, nc1, so, nl = -1, nr = -1;
    if (!PyArg_ParseTuple(args, "OOOO", &orows, &ol, &orr, &oo))
        return NULL;
    const double *x = get_matrix(&bs, orows, 0, &rows, &cols, &sr, "rows");
    double *out = x ? get_matrix(&bs, oo, 1, &rows_o, &nc1, &so, "out") : NULL;
    const double *left = out ? get(&bs, ol, 0, &nl, "left") : NULL;
    const double *right = left ? get(&bs, orr, 0, &nr, "right") : NULL;
    Py_ssize_t nc = nc1 - 1;
    if (right != NULL
        && (nl != nc || nr != nc || rows_o != rows || cols != 2 * nc + 1 || nc < 1)) {
        PyErr_SetString(PyExc_ValueError, "restrict needs rows (R, 2 Nc + 1), left and right "
                                          "(Nc,) float64 and out (R, Nc + 1), Nc >= 1");
        right = NULL;
    }
    if (right == NULL) {
        release(&bs);
        return NULL;
    }
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t i = 0; i < rows; i++) {
        const double *xi = x + i * sr;
        double *oi = out + i * so;
        for (Py_ssize_t j = 0; j < nc; j++)
            oi[j] = xi[2 * j] + xi[2 * j + 1] * left[j];
        oi[nc] = xi[2 * nc];
        for (Py_ssize_t j = 1; j <= nc; j++)
            oi[j] = oi[j] + xi[2 * j - 1] * right[j - 1];
    }
    Py_END_ALLOW_THREADS
    release(&bs);
    Py_RETURN_NONE;
}

/* classify(x, lo, hi, inv_len, dist_ref, thresholds, order, offsets): the (point, element)
 * pairs of influence.element_integrals' row block grouped by key, as its numpy route does it:
 * dist = max(lo - x, x - hi, 0) inv_len (min with dist_ref when it has n values), key =
 * (lo - x >= 0) + 2 (number of thresholds <= dist); pairs p = i n + j. Bucket 0 holds the
 * keys 0 and 1 (the near pairs, np.flatnonzero(key < 2)), bucket b >= 2 the key b
 * (np.flatnonzero(key == b)), each in increasing p; offsets (2 T + 3) delimit the buckets
 * in order (int64). NaN distances compare false, as in numpy. */
static PyObject *py_classify(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *o[8];
    bufs_t bs = {.n = 0};
    if (!PyArg_ParseTuple(args, "OOOOOOOO", &o[0], &o[1], &o[2], &o[3], &o[4], &o[5], &o[6],
                          &o[7]))
        return NULL;
    Py_ssize_t mb = -1, n = -1, n2 = -1, n3 = -1, nref = -1, nt = -1, nord, noff;
    const double *x = get(&bs, o[0], 0, &mb, "x");
    const double *lo = x ? get(&bs, o[1], 0, &n, "lo") : NULL;
    const double *hi = lo ? get(&bs, o[2], 0, &n2, "hi") : NULL;
    const double *il = hi ? get(&bs, o[3], 0, &n3, "inv_len") : NULL;
    const double *ref = il ? get(&bs, o[4], 0, &nref, "dist_ref") : NULL;
    const double *thr = ref ? get(&bs, o[5], 0, &nt, "thresholds") : NULL;
    long long *order = thr ? get_int64(&bs, o[6], 1, &nord, "order") : NULL;
    long long *off = order ? get_int64(&bs, o[7], 1, &noff, "offsets") : NULL;
    Py_ssize_t nkeys = 2 * nt + 2;
    if (off != NULL && (n2 != n || n3 != n || nord != mb * n || noff != nkeys + 1 || nt > 60)) {
        PyErr_SetString(PyExc_ValueError, "classify: inconsistent lengths");
        off = NULL;
    }
    if (off == NULL) {
        release(&bs);
        return NULL;
    }
    int use_ref = nref == n && n > 0;
    {
        signed char *key = PyMem_Malloc(mb * n > 0 ? (size_t)(mb * n) : 1);
        if (key == NULL) {
            release(&bs);
            return PyErr_NoMemory();
        }
        Py_BEGIN_ALLOW_THREADS
        long long count[128] = {0};
        for (Py_ssize_t i = 0; i < mb; i++) {
            for (Py_ssize_t j = 0; j < n; j++) {
                double d = lo[j] - x[i], t = x[i] - hi[j];
                int side = d >= 0.0, c = side;
                /* np.maximum propagates NaN */
                d = (d != d || t != t) ? NAN : (d >= t ? d : t);
                d = (d != d) ? d : (d >= 0.0 ? d : 0.0);
                d = d * il[j];
                if (use_ref)
                    d = (d != d || ref[j] != ref[j]) ? NAN : (d <= ref[j] ? d : ref[j]);
                for (Py_ssize_t q = 0; q < nt; q++)
                    c += 2 * (d >= thr[q]);
                c = c < 2 ? 0 : c; /* the near bucket */
                key[i * n + j] = (signed char)c;
                count[c]++;
            }
        }
        off[0] = 0;
        for (Py_ssize_t c = 0; c < nkeys; c++)
            off[c + 1] = off[c] + count[c];
        long long fill[128];
        for (Py_ssize_t c = 0; c < nkeys; c++)
            fill[c] = off[c];
        for (Py_ssize_t p = 0; p < mb * n; p++)
            order[fill[key[p]]++] = p;
        Py_END_ALLOW_THREADS
        PyMem_Free(key);
    }
    release(&bs);
    Py_RETURN_NONE;
}

static PyMethodDef methods[] = {
    {"classify", py_classify, METH_VARARGS,
     "classify(x, lo, hi, inv_len, dist_ref, thresholds, order, offsets): the pairs of a row "
     "block grouped by key (see contactlib.discretization.influence.element_integrals)."},
    {"restrict", py_restrict, METH_VARARGS,
     "restrict(rows, left, right, out): the nested coarse columns of fine rows (see "
     "contactlib.discretization.operators.restrict_nested)."},
    {"difference", py_difference, METH_VARARGS,
     "difference(g, h, out): out[:, l] = g[:, l]/h[l] - g[:, l-1]/h[l-1] (see "
     "contactlib.discretization.influence.apply_difference)."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "operators_fused",
                                    "Fused steps of the nodal operators (see contactlib.discretization.influence, contactlib.discretization.operators).", -1,
                                    methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit_operators_fused(void) { return PyModule_Create(&module); }
