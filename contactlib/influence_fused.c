/* contactlib.influence.apply_difference, fused: element integrals -> nodal operators in one
 * pass over the rows instead of three numpy passes (scale, subtract, negate).
 *
 * For each row: s_l = g_l / h_l, then out_0 = s_0, out_l = s_l - s_{l-1}, out_N = -s_{N-1}:
 * the numpy route's operations on the same operands, so the same bits
 * (tests/test_kernels_fused.py). `g` may be the first N columns of `out` (the operator built
 * in place): a row's g_l is read before out_l is written, and out_l is never read again.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

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

static PyMethodDef methods[] = {
    {"difference", py_difference, METH_VARARGS,
     "difference(g, h, out): out[:, l] = g[:, l]/h[l] - g[:, l-1]/h[l-1] (see "
     "contactlib.influence.apply_difference)."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "influence_fused",
                                    "Fused apply_difference (see contactlib.influence).", -1,
                                    methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit_influence_fused(void) { return PyModule_Create(&module); }
