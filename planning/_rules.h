/*
 * The tables the grid searches (_strip.c, _tidy.c, _regroup.c) take from
 * Python once,
 * and the few look-ups both make with them. No geometry lives here: the
 * Python side hands over the 12 cells around a mobile module, the Table
 * 4-3 rotations (substrate bit, goal and swept bits, substrate and goal
 * offsets) in ROTATIONS order, the six sides, and one table over the 64
 * rings of six neighbours (which one is the pass's to say).
 */
#ifndef HEXBOT_PLANNING_RULES_H
#define HEXBOT_PLANNING_RULES_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>

#define RING 12
#define SIDES 6
#define MAX_RULES 16

static int ring_dx[RING], ring_dy[RING];
static int side_dx[SIDES], side_dy[SIDES];
static uint8_t ring_table[64];  /* per ring of six (bit i: side i occupied) */
static int rule_count;
static uint16_t rule_sub[MAX_RULES], rule_free[MAX_RULES];
static int rule_sx[MAX_RULES], rule_sy[MAX_RULES], rule_gx[MAX_RULES], rule_gy[MAX_RULES];
static int rules_set;

static int read_pairs(PyObject *seq, int count, int *xs, int *ys, const char *what)
{
    PyObject *f = PySequence_Fast(seq, what);
    if (!f)
        return -1;
    if (PySequence_Fast_GET_SIZE(f) != count) {
        PyErr_Format(PyExc_ValueError, "set_rules: %s needs %d (dx, dy) pairs", what, count);
        Py_DECREF(f);
        return -1;
    }
    for (int i = 0; i < count; i++)
        if (!PyArg_ParseTuple(PySequence_Fast_GET_ITEM(f, i), "ii", &xs[i], &ys[i])) {
            Py_DECREF(f);
            return -1;
        }
    Py_DECREF(f);
    return 0;
}

/* set_rules(ring, rotations, sides[, table]): ring = 12 (dx, dy); rotations
 * = (substrate bit, goal and swept bits, substrate dx, dy, goal dx, dy) in
 * ROTATIONS order; sides = 6 (dx, dy) in side order; table = 64 booleans
 * over the rings of six, named `table_name` in errors (NULL: no table). */
static PyObject *read_rules(PyObject *args, const char *table_name)
{
    PyObject *ring, *rotations, *sides, *table = NULL;
    if (table_name ? !PyArg_ParseTuple(args, "OOOO", &ring, &rotations, &sides, &table)
                   : !PyArg_ParseTuple(args, "OOO", &ring, &rotations, &sides))
        return NULL;
    if (read_pairs(ring, RING, ring_dx, ring_dy, "ring") < 0
        || read_pairs(sides, SIDES, side_dx, side_dy, "sides") < 0)
        return NULL;
    PyObject *t = PySequence_Fast(rotations, "rotations");
    if (!t)
        return NULL;
    PyObject *a = table ? PySequence_Fast(table, table_name) : PyTuple_New(0);
    if (!a) {
        Py_DECREF(t);
        return NULL;
    }
    Py_ssize_t nr = PySequence_Fast_GET_SIZE(t);
    if (nr < 1 || nr > MAX_RULES || (table && PySequence_Fast_GET_SIZE(a) != 64)) {
        PyErr_Format(PyExc_ValueError, "set_rules: 1-16 rotations%s%s", table ? ", 64 of " : "",
                     table ? table_name : "");
        goto fail;
    }
    for (int i = 0; i < nr; i++) {
        unsigned sub, free_bits;
        if (!PyArg_ParseTuple(PySequence_Fast_GET_ITEM(t, i), "IIiiii", &sub, &free_bits,
                              &rule_sx[i], &rule_sy[i], &rule_gx[i], &rule_gy[i]))
            goto fail;
        rule_sub[i] = (uint16_t)sub, rule_free[i] = (uint16_t)free_bits;
    }
    for (int i = 0; table && i < 64; i++) {
        int truth = PyObject_IsTrue(PySequence_Fast_GET_ITEM(a, i));
        if (truth < 0)
            goto fail;
        ring_table[i] = (uint8_t)truth;
    }
    rule_count = (int)nr;
    rules_set = 1;
    Py_DECREF(t), Py_DECREF(a);
    Py_RETURN_NONE;
fail:
    Py_DECREF(t), Py_DECREF(a);
    return NULL;
}

/* The lattice distance between grid cells a and b of a grid `w` wide and
 * `h` high: `dist` holds it by offset, (dx, dy) at (dx + w - 1) + (dy + h -
 * 1) * (2 w - 1). */
static inline int32_t grid_distance(const int32_t *dist, int w, int h, int32_t a, int32_t b)
{
    int dx = a % w - b % w, dy = a / w - b / w;
    return dist[(dx + w - 1) + (size_t)(dy + h - 1) * (2 * w - 1)];
}

/* Is rotation r open to a module whose ring of 12 is `mask`? */
static inline int is_open(unsigned mask, int r)
{
    return (mask & rule_sub[r]) && !(mask & rule_free[r]);
}

#endif
