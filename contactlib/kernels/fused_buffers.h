/* What the compiled kernels of contactlib share: float64 buffers of the arguments, held
 * and released together. Included by disc_fused.c and strip_fused.c. */
#ifndef CONTACTLIB_FUSED_BUFFERS_H
#define CONTACTLIB_FUSED_BUFFERS_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <string.h>

#define MAX_BUFFERS 12

/* CLONES: loops over points built for AVX2 and for the baseline (chosen at load time) where
 * the compiler can; wider vectors of the same IEEE operations (no FMA: -ffp-contract=off),
 * so the same bits */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CLONES __attribute__((target_clones("avx2", "default")))
#else
#define CLONES
#endif

typedef struct {
    Py_buffer b[MAX_BUFFERS];
    int n;
} bufs_t;

static void release(bufs_t *bs)
{
    for (int i = 0; i < bs->n; i++)
        PyBuffer_Release(&bs->b[i]);
    bs->n = 0;
}

/* a contiguous float64 buffer of *k doubles (*k < 0: any length, then set), held in bs;
 * NULL with an exception set (bs still to be released) */
static double *get(bufs_t *bs, PyObject *obj, int writable, Py_ssize_t *k, const char *name)
{
    if (bs->n >= MAX_BUFFERS) {
        PyErr_SetString(PyExc_RuntimeError, "too many buffers");
        return NULL;
    }
    Py_buffer *v = &bs->b[bs->n];
    int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
    if (PyObject_GetBuffer(obj, v, flags) != 0)
        return NULL;
    bs->n++;
    if (v->itemsize != 8 || v->format == NULL || strcmp(v->format, "d") != 0) {
        PyErr_Format(PyExc_TypeError, "%s must be a contiguous float64 array", name);
        return NULL;
    }
    Py_ssize_t len = v->len / 8;
    if (*k >= 0 && len != *k) {
        PyErr_Format(PyExc_ValueError, "%s has %zd values, expected %zd", name, len, *k);
        return NULL;
    }
    *k = len;
    return (double *)v->buf;
}

#endif
