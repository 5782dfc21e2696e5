/* Two steps of building nodal operators, fused: one pass over each row where numpy makes
 * several. Both are the numpy routes' operations on the same operands in the same order, so
 * the same bits (tests/test_kernels_fused.py); built with -ffp-contract=off.
 *
 * difference: contactlib.influence.apply_difference, element integrals -> nodal operators
 * (numpy: scale, subtract, negate).
 * For each row: s_l = g_l / h_l, then out_0 = s_0, out_l = s_l - s_{l-1}, out_N = -s_{N-1}:
 * the numpy route's operations on the same operands, so the same bits
 * (tests/test_kernels_fused.py). `g` may be the first N columns of `out` (the operator built
 * in place): a row's g_l is read before out_l is written, and out_l is never read again.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <string.h>

/* a 2-d float64 buffer with a contiguous last axis (any row stride), or NULL */
static double *matrix(PyObject *obj, Py_buffer *v, int writable, Py_ssize_t *rows,
                      Py_ssize_t *cols, Py_ssize_t *stride, const char *name)
{
    if (PyObject_GetBuffer(obj, v, PyBUF_STRIDES | PyBUF_FORMAT
                                       | (writable ? PyBUF_WRITABLE : 0)) != 0)
        return NULL;
    if (v->ndim != 2 || v->itemsize != 8 || v->format == NULL || strcmp(v->format, "d") != 0
        || (v->shape[1] > 1 && v->strides[1] != 8) || v->strides[0] % 8 != 0) {
        PyErr_Format(PyExc_TypeError,
                     "%s must be a 2-d float64 array with a contiguous last axis", name);
        PyBuffer_Release(v);
        return NULL;
    }
    *rows = v->shape[0], *cols = v->shape[1], *stride = v->strides[0] / 8;
    return (double *)v->buf;
}

/* restrict: contactlib.operators.restrict_nested, the fine columns of rows combined into the
 * coarse ones, out_j = (even_j + odd_j left_j) + odd_{j-1} right_{j-1} (numpy: copy, two
 * products, two shifted additions). */

/* difference(g, h, out): g (rows, N), h (N,) element lengths, out (rows, N + 1) */
static PyObject *py_difference(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *og, *oh, *oo;
    Py_buffer vg, vh, vo;
    Py_ssize_t rows, n, sg, rows_o, n1, so;
    if (!PyArg_ParseTuple(args, "OOO", &og, &oh, &oo))
        return NULL;
    const double *g = matrix(og, &vg, 0, &rows, &n, &sg, "g");
    if (g == NULL)
        return NULL;
    double *out = matrix(oo, &vo, 1, &rows_o, &n1, &so, "out");
    if (out == NULL) {
        PyBuffer_Release(&vg);
        return NULL;
    }
    if (PyObject_GetBuffer(oh, &vh, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) != 0) {
        PyBuffer_Release(&vg);
        PyBuffer_Release(&vo);
        return NULL;
    }
    if (vh.itemsize != 8 || vh.format == NULL || strcmp(vh.format, "d") != 0
        || vh.len / 8 != n || rows_o != rows || n1 != n + 1 || n < 1) {
        PyErr_SetString(PyExc_ValueError, "difference needs g (rows, N), h (N,) float64 and "
                                          "out (rows, N + 1), N >= 1");
        PyBuffer_Release(&vg);
        PyBuffer_Release(&vo);
        PyBuffer_Release(&vh);
        return NULL;
    }
    const double *h = (const double *)vh.buf;
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
    PyBuffer_Release(&vg);
    PyBuffer_Release(&vo);
    PyBuffer_Release(&vh);
    Py_RETURN_NONE;
}

/* restrict(rows, left, right, out): rows (R, 2 Nc + 1), left and right (Nc,), out (R, Nc + 1) */
static PyObject *py_restrict(PyObject *Py_UNUSED(self), PyObject *args)
{
    PyObject *orows, *ol, *orr, *oo;
    Py_buffer vr, vl, vrr, vo;
    Py_ssize_t rows, cols, sr, rows_o, nc1, so;
    if (!PyArg_ParseTuple(args, "OOOO", &orows, &ol, &orr, &oo))
        return NULL;
    const double *x = matrix(orows, &vr, 0, &rows, &cols, &sr, "rows");
    if (x == NULL)
        return NULL;
    double *out = matrix(oo, &vo, 1, &rows_o, &nc1, &so, "out");
    if (out == NULL) {
        PyBuffer_Release(&vr);
        return NULL;
    }
    if (PyObject_GetBuffer(ol, &vl, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) != 0) {
        PyBuffer_Release(&vr);
        PyBuffer_Release(&vo);
        return NULL;
    }
    if (PyObject_GetBuffer(orr, &vrr, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) != 0) {
        PyBuffer_Release(&vr);
        PyBuffer_Release(&vo);
        PyBuffer_Release(&vl);
        return NULL;
    }
    Py_ssize_t nc = nc1 - 1;
    if (vl.itemsize != 8 || vrr.itemsize != 8 || vl.format == NULL || vrr.format == NULL
        || strcmp(vl.format, "d") != 0 || strcmp(vrr.format, "d") != 0 || vl.len / 8 != nc
        || vrr.len / 8 != nc || rows_o != rows || cols != 2 * nc + 1 || nc < 1) {
        PyErr_SetString(PyExc_ValueError, "restrict needs rows (R, 2 Nc + 1), left and right "
                                          "(Nc,) float64 and out (R, Nc + 1), Nc >= 1");
        PyBuffer_Release(&vr);
        PyBuffer_Release(&vo);
        PyBuffer_Release(&vl);
        PyBuffer_Release(&vrr);
        return NULL;
    }
    const double *left = (const double *)vl.buf, *right = (const double *)vrr.buf;
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
    PyBuffer_Release(&vr);
    PyBuffer_Release(&vo);
    PyBuffer_Release(&vl);
    PyBuffer_Release(&vrr);
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
    PyObject *ox, *olo, *ohi, *oil, *oref, *othr, *oord, *ooff;
    Py_buffer b[8];
    int held = 0;
    if (!PyArg_ParseTuple(args, "OOOOOOOO", &ox, &olo, &ohi, &oil, &oref, &othr, &oord, &ooff))
        return NULL;
    PyObject *objs[8] = {ox, olo, ohi, oil, oref, othr, oord, ooff};
    for (; held < 8; held++) {
        int w = held >= 6;
        if (PyObject_GetBuffer(objs[held], &b[held], PyBUF_C_CONTIGUOUS | PyBUF_FORMAT
                                                         | (w ? PyBUF_WRITABLE : 0)) != 0)
            goto fail;
        if (b[held].itemsize != 8 || b[held].format == NULL
            || strchr(w ? "qlL" : "d", b[held].format[0]) == NULL) {
            held++;
            PyErr_SetString(PyExc_TypeError, "classify needs float64 inputs and int64 outputs");
            goto fail;
        }
    }
    {
        const double *x = b[0].buf, *lo = b[1].buf, *hi = b[2].buf, *il = b[3].buf,
                     *ref = b[4].buf, *thr = b[5].buf;
        Py_ssize_t mb = b[0].len / 8, n = b[1].len / 8, nt = b[5].len / 8;
        int use_ref = b[4].len / 8 == n && n > 0;
        long long *order = b[6].buf, *off = b[7].buf;
        Py_ssize_t nkeys = 2 * nt + 2;
        if (b[2].len / 8 != n || b[3].len / 8 != n || b[6].len / 8 != mb * n
            || b[7].len / 8 != nkeys + 1 || nt > 60) {
            PyErr_SetString(PyExc_ValueError, "classify: inconsistent lengths");
            goto fail;
        }
        signed char *key = PyMem_Malloc(mb * n > 0 ? (size_t)(mb * n) : 1);
        if (key == NULL) {
            PyErr_NoMemory();
            goto fail;
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
    for (int i = 0; i < held; i++)
        PyBuffer_Release(&b[i]);
    Py_RETURN_NONE;
fail:
    for (int i = 0; i < held; i++)
        PyBuffer_Release(&b[i]);
    return NULL;
}

static PyMethodDef methods[] = {
    {"classify", py_classify, METH_VARARGS,
     "classify(x, lo, hi, inv_len, dist_ref, thresholds, order, offsets): the pairs of a row "
     "block grouped by key (see contactlib.influence.element_integrals)."},
    {"restrict", py_restrict, METH_VARARGS,
     "restrict(rows, left, right, out): the nested coarse columns of fine rows (see "
     "contactlib.operators.restrict_nested)."},
    {"difference", py_difference, METH_VARARGS,
     "difference(g, h, out): out[:, l] = g[:, l]/h[l] - g[:, l-1]/h[l-1] (see "
     "contactlib.influence.apply_difference)."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "operators_fused",
                                    "Fused steps of the nodal operators (see contactlib.influence, contactlib.operators).", -1,
                                    methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit_operators_fused(void) { return PyModule_Create(&module); }
