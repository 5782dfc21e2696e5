/* What the compiled parts of contactlib share: the buffers of their arguments (float64
 * vectors and matrices, int64 vectors), checked, held and released together. Included by
 * kernels/disc_fused.c, kernels/strip_fused.c, operators_fused.c and solver_fused.c. */
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

static inline void release(bufs_t *bs)
{
    for (int i = 0; i < bs->n; i++)
        PyBuffer_Release(&bs->b[i]);
    bs->n = 0;
}

/* the buffer of obj held in bs (flags as PyObject_GetBuffer's, writable added), its items
 * 8 bytes of one of the struct formats `formats` ("d": float64, "qlL": int64); NULL with an
 * exception set (bs still to be released) */
static inline Py_buffer *hold(bufs_t *bs, PyObject *obj, int flags, int writable,
                              const char *formats, const char *name, const char *kind)
{
    if (bs->n >= MAX_BUFFERS) {
        PyErr_SetString(PyExc_RuntimeError, "too many buffers");
        return NULL;
    }
    Py_buffer *v = &bs->b[bs->n];
    if (PyObject_GetBuffer(obj, v, flags | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0)) != 0)
        return NULL;
    bs->n++;
    if (v->itemsize != 8 || v->format == NULL || v->format[0] == '\0'
        || strchr(formats, v->format[0]) == NULL || v->format[1] != '\0') {
        PyErr_Format(PyExc_TypeError, "%s must be a %s array", name, kind);
        return NULL;
    }
    return v;
}

/* a contiguous float64 buffer of *k doubles (*k < 0: any length, then set), held in bs;
 * NULL with an exception set (bs still to be released) */
static inline double *get(bufs_t *bs, PyObject *obj, int writable, Py_ssize_t *k, const char *name)
{
    Py_buffer *v = hold(bs, obj, PyBUF_C_CONTIGUOUS, writable, "d", name,
                        "contiguous float64");
    if (v == NULL)
        return NULL;
    Py_ssize_t len = v->len / 8;
    if (*k >= 0 && len != *k) {
        PyErr_Format(PyExc_ValueError, "%s has %zd values, expected %zd", name, len, *k);
        return NULL;
    }
    *k = len;
    return (double *)v->buf;
}

/* a contiguous int64 buffer, its length in *k; as get() */
static inline long long *get_int64(bufs_t *bs, PyObject *obj, int writable, Py_ssize_t *k,
                                   const char *name)
{
    Py_buffer *v = hold(bs, obj, PyBUF_C_CONTIGUOUS, writable, "qlL", name,
                        "contiguous int64");
    if (v == NULL)
        return NULL;
    *k = v->len / 8;
    return (long long *)v->buf;
}

/* a 2-d float64 buffer with a contiguous last axis (any row stride, in items), held in bs;
 * NULL with an exception set (bs still to be released) */
static inline double *get_matrix(bufs_t *bs, PyObject *obj, int writable, Py_ssize_t *rows,
                                 Py_ssize_t *cols, Py_ssize_t *stride, const char *name)
{
    Py_buffer *v = hold(bs, obj, PyBUF_STRIDES, writable, "d", name,
                        "2-d float64 (contiguous last axis)");
    if (v == NULL)
        return NULL;
    if (v->ndim != 2 || (v->shape[1] > 1 && v->strides[1] != 8) || v->strides[0] % 8 != 0) {
        PyErr_Format(PyExc_TypeError, "%s must be a 2-d float64 array with a contiguous last "
                     "axis", name);
        return NULL;
    }
    *rows = v->shape[0], *cols = v->shape[1], *stride = v->strides[0] / 8;
    return (double *)v->buf;
}

/* the objects obj[0..count) as float64 vectors of one length (the last `written` writable),
 * their data in out and the length in *k; 0, or -1 with an exception set */
static inline int get_vectors(bufs_t *bs, PyObject *const *obj, int count, int written,
                              double **out, Py_ssize_t *k, const char *const *names)
{
    *k = -1;
    for (int i = 0; i < count; i++) {
        out[i] = get(bs, obj[i], i >= count - written, k, names[i]);
        if (out[i] == NULL)
            return -1;
    }
    return 0;
}

#endif
