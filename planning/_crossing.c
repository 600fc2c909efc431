/*
 * hexbot.planning._crossing: the A* of a journey's crossing, in C.
 *
 * journey.crossing() spends most of a large plan's time here (blob of 1,000:
 * 6-9 s of 10-14 s in Python). The search is the same, state for state: this
 * file holds no geometry. journey.py hands over, once, each disc's index
 * tables (_Disc) and the rule tables (_LEAVABLE, _OPEN12 by goal); a search
 * then gets bit masks and returns the hops as indices that journey.py turns
 * back into cells and rules.
 *
 * A state is the window's occupancy, one bit per window cell (radius 3: 37
 * cells, so 64 bits do). The modules on the two rings around the window never
 * move; they are `outside`, bits size.. of a 128-bit "whole" mask.
 *
 * Expansion order is Python's: heap key (f, creation order), movers by
 * ascending bit, a mover's rotations in _OPEN12 order; a state is accepted
 * when generated. Equal inputs give equal hops in both implementations
 * (tests/planning/test_planning_crossing.py compares them).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef unsigned __int128 u128;

#define MAX_DISCS 8
#define MAX_CELLS 128   /* window + two rings: 91 cells at radius 3 */
#define MAX_WINDOW 64   /* a state is one 64-bit word */
#define MAX_GOALS 16    /* distinct goal offsets of the rotations (6) */
#define MAX_OPEN 16     /* rotations open under one 12-cell mask */

typedef struct {
    int size, ncells, center;
    uint8_t ring6[MAX_WINDOW][6];
    uint8_t ring12[MAX_WINDOW][12];
    uint64_t near[MAX_WINDOW];               /* a cell and its neighbours, window bits */
    int8_t goal_index[MAX_WINDOW][MAX_GOALS]; /* window index of cell + goal, or -1 */
} Disc;

static Disc discs[MAX_DISCS];
static int disc_count;

static uint8_t leavable[64];
static uint8_t open_count[4096];
static uint8_t open_goal[4096][MAX_OPEN];  /* goal codes, in _OPEN12 order */
static int rules_set;

typedef struct {
    uint64_t state, movable;
    int32_t parent;
    uint16_t mask;       /* the mover's 12-cell mask when this state was made */
    uint8_t mover, target, option, has_movable;
    int32_t cost;
} Node;

typedef struct { int32_t f, node; } HeapItem;

static inline int bit(u128 whole, int i) { return (int)((whole >> i) & 1); }

static inline int leaves(u128 whole, const uint8_t *r)
{
    return leavable[bit(whole, r[0]) | bit(whole, r[1]) << 1 | bit(whole, r[2]) << 2
                    | bit(whole, r[3]) << 3 | bit(whole, r[4]) << 4 | bit(whole, r[5]) << 5];
}

static inline int heap_less(HeapItem a, HeapItem b)
{
    return a.f < b.f || (a.f == b.f && a.node < b.node);
}

static void heap_push(HeapItem *heap, int *n, HeapItem item)
{
    int i = (*n)++;
    while (i > 0) {
        int up = (i - 1) / 2;
        if (!heap_less(item, heap[up]))
            break;
        heap[i] = heap[up];
        i = up;
    }
    heap[i] = item;
}

static HeapItem heap_pop(HeapItem *heap, int *n)
{
    HeapItem top = heap[0], last = heap[--(*n)];
    int i = 0;
    for (;;) {
        int child = 2 * i + 1;
        if (child >= *n)
            break;
        if (child + 1 < *n && heap_less(heap[child + 1], heap[child]))
            child++;
        if (!heap_less(heap[child], last))
            break;
        heap[i] = heap[child];
        i = child;
    }
    heap[i] = last;
    return top;
}

/* Open addressing, state -> node index + 1 (0 = empty). */
static inline uint64_t mix(uint64_t x)
{
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    return x;
}

static int32_t *find_slot(int32_t *table, uint64_t mask, const Node *nodes, uint64_t state)
{
    uint64_t i = mix(state) & mask;
    while (table[i] && nodes[table[i] - 1].state != state)
        i = (i + 1) & mask;
    return &table[i];
}

static PyObject *hops_list(const Node *nodes, int last)
{
    int length = 0;
    for (int i = last; nodes[i].parent >= 0; i = nodes[i].parent)
        length++;
    PyObject *list = PyList_New(length);
    if (!list)
        return NULL;
    for (int i = last; nodes[i].parent >= 0; i = nodes[i].parent) {
        const Node *n = &nodes[i];
        PyObject *hop = Py_BuildValue("(iiii)", n->mover, n->target, n->mask, n->option);
        if (!hop) {
            Py_DECREF(list);
            return NULL;
        }
        PyList_SET_ITEM(list, --length, hop);
    }
    return list;
}

static PyObject *search(PyObject *self, PyObject *args)
{
    int id, max_states;
    unsigned long long start, out_lo, out_hi, pinned, nearer;
    if (!PyArg_ParseTuple(args, "iKKKKKi", &id, &start, &out_lo, &out_hi, &pinned,
                          &nearer, &max_states))
        return NULL;
    if (!rules_set || id < 0 || id >= disc_count || max_states < 1) {
        PyErr_SetString(PyExc_ValueError, "crossing search: tables not set up or bad arguments");
        return NULL;
    }
    const Disc *d = &discs[id];
    const u128 outside = (u128)out_hi << 64 | out_lo;
    const uint64_t window = d->size == 64 ? ~0ULL : (1ULL << d->size) - 1;
    const uint64_t home = start & ~(1ULL << d->center);

    /* One node per state, each pushed at most once; the last expansion may add
     * up to MAX_WINDOW * MAX_OPEN states past max_states. */
    const size_t room = (size_t)max_states + MAX_WINDOW * MAX_OPEN;
    uint64_t capacity = 16;
    while (capacity < 2 * (uint64_t)room)
        capacity <<= 1;
    Node *nodes = malloc(sizeof(Node) * room);
    HeapItem *heap = malloc(sizeof(HeapItem) * room);
    int32_t *table = calloc(capacity, sizeof(int32_t));
    if (!nodes || !heap || !table) {
        free(nodes), free(heap), free(table);
        return PyErr_NoMemory();
    }
    const uint64_t slots = capacity - 1;
    PyObject *result = NULL;
    int count = 1, heap_size = 0, found = -1;

    u128 whole = outside | start;
    uint64_t free0 = 0;
    for (int i = 0; i < d->size; i++)
        if ((start >> i & 1) && leaves(whole, d->ring6[i]))
            free0 |= 1ULL << i;
    nodes[0] = (Node){ .state = start, .movable = free0 & ~pinned, .parent = -1,
                       .has_movable = 1, .cost = 0 };
    *find_slot(table, slots, nodes, start) = 1;
    heap_push(heap, &heap_size, (HeapItem){ 1, 0 });

    while (heap_size && count < max_states && found < 0) {
        int at = heap_pop(heap, &heap_size).node;
        Node *node = &nodes[at];
        uint64_t state = node->state;
        whole = outside | state;
        if (!node->has_movable) {
            const Node *before = &nodes[node->parent];
            uint64_t changed = before->state ^ state;
            int src = __builtin_ctzll(changed), dst = 63 - __builtin_clzll(changed);
            uint64_t around = d->near[src] | d->near[dst];
            uint64_t movable = before->movable & ~around;
            uint64_t check = around & state & ~pinned;
            while (check) {
                int i = __builtin_ctzll(check);
                check &= check - 1;
                if (leaves(whole, d->ring6[i]))
                    movable |= 1ULL << i;
            }
            node->movable = movable;
            node->has_movable = 1;
        }
        uint64_t movers = node->movable;
        int32_t after_cost = node->cost + 1;
        while (movers && found < 0) {
            int i = __builtin_ctzll(movers);
            uint64_t low = movers & -movers;
            movers &= movers - 1;
            const uint8_t *r = d->ring12[i];
            unsigned mask = 0;
            for (int b = 0; b < 12; b++)
                mask |= (unsigned)bit(whole, r[b]) << b;
            for (int k = 0; k < open_count[mask]; k++) {
                int target = d->goal_index[i][open_goal[mask][k]];
                if (target < 0)
                    continue;
                uint64_t after = state ^ low ^ (1ULL << target);
                int32_t *slot = find_slot(table, slots, nodes, after);
                if (*slot)
                    continue;
                nodes[count] = (Node){ .state = after, .parent = at, .mask = (uint16_t)mask,
                                       .mover = (uint8_t)i, .target = (uint8_t)target,
                                       .option = (uint8_t)k, .cost = after_cost };
                *slot = count + 1;
                uint64_t arrived = after & ~home & window;
                int away = __builtin_popcountll(home & ~after);
                if (away == 0 && (arrived & nearer)) {
                    found = count++;
                    break;
                }
                heap_push(heap, &heap_size, (HeapItem){ after_cost + away + 1, count });
                count++;
            }
        }
    }
    if (found >= 0) {
        PyObject *hops = hops_list(nodes, found);
        uint64_t arrived = nodes[found].state & ~home;
        result = hops ? Py_BuildValue("(Ni)", hops, __builtin_ctzll(arrived)) : NULL;
    } else
        result = Py_NewRef(Py_None);
    free(nodes), free(heap), free(table);
    return result;
}

static int int_list(PyObject *seq, int *out, int length, const char *what)
{
    PyObject *fast = PySequence_Fast(seq, what);
    if (!fast)
        return -1;
    if (PySequence_Fast_GET_SIZE(fast) != length) {
        PyErr_Format(PyExc_ValueError, "%s: %d items expected", what, length);
        Py_DECREF(fast);
        return -1;
    }
    for (int i = 0; i < length; i++) {
        out[i] = (int)PyLong_AsLong(PySequence_Fast_GET_ITEM(fast, i));
        if (out[i] == -1 && PyErr_Occurred()) {
            Py_DECREF(fast);
            return -1;
        }
    }
    Py_DECREF(fast);
    return 0;
}

/* set_rules(leavable: 64 bools, open_goals: 4096 sequences of goal codes)
 * The tables are read and checked whole before any is replaced: refused rules
 * leave the search as it was. */
static PyObject *set_rules(PyObject *self, PyObject *args)
{
    PyObject *leave, *open;
    if (!PyArg_ParseTuple(args, "OO", &leave, &open))
        return NULL;
    int values[64];
    if (int_list(leave, values, 64, "leavable") < 0)
        return NULL;
    PyObject *fast = PySequence_Fast(open, "open goals");
    if (!fast)
        return NULL;
    if (PySequence_Fast_GET_SIZE(fast) != 4096) {
        Py_DECREF(fast);
        PyErr_SetString(PyExc_ValueError, "open goals: 4096 masks expected");
        return NULL;
    }
    static uint8_t new_count[4096];
    static uint8_t new_goal[4096][MAX_OPEN];
    for (int m = 0; m < 4096; m++) {
        PyObject *goals = PySequence_Fast_GET_ITEM(fast, m);
        Py_ssize_t n = PySequence_Size(goals);
        if (n < 0 || n > MAX_OPEN) {
            Py_DECREF(fast);
            PyErr_SetString(PyExc_ValueError, "open goals: too many rotations under one mask");
            return NULL;
        }
        int codes[MAX_OPEN];
        if (int_list(goals, codes, (int)n, "open goals") < 0) {
            Py_DECREF(fast);
            return NULL;
        }
        new_count[m] = (uint8_t)n;
        for (int k = 0; k < n; k++) {
            if (codes[k] < 0 || codes[k] >= MAX_GOALS) {
                Py_DECREF(fast);
                PyErr_SetString(PyExc_ValueError, "open goals: goal code out of range");
                return NULL;
            }
            new_goal[m][k] = (uint8_t)codes[k];
        }
    }
    Py_DECREF(fast);
    for (int i = 0; i < 64; i++)
        leavable[i] = (uint8_t)(values[i] != 0);
    memcpy(open_count, new_count, sizeof open_count);
    memcpy(open_goal, new_goal, sizeof open_goal);
    rules_set = 1;
    Py_RETURN_NONE;
}

/* add_disc(size, ncells, center, ring6 (size*6), ring12 (size*12), near (size),
 *          goal_index (size*goals), goals) -> id */
static PyObject *add_disc(PyObject *self, PyObject *args)
{
    int size, ncells, center, goals;
    PyObject *ring6, *ring12, *near, *goal_index;
    if (!PyArg_ParseTuple(args, "iiiOOOOi", &size, &ncells, &center, &ring6, &ring12, &near,
                          &goal_index, &goals))
        return NULL;
    if (disc_count == MAX_DISCS || size < 1 || size > MAX_WINDOW || ncells > MAX_CELLS
        || ncells < size || center < 0 || center >= size || goals < 1 || goals > MAX_GOALS) {
        PyErr_SetString(PyExc_ValueError, "add_disc: disc too large or too many discs");
        return NULL;
    }
    Disc *d = &discs[disc_count];
    static int buffer[MAX_WINDOW * MAX_GOALS];
    d->size = size, d->ncells = ncells, d->center = center;
    if (int_list(ring6, buffer, size * 6, "ring6") < 0)
        return NULL;
    for (int i = 0; i < size * 6; i++)
        d->ring6[i / 6][i % 6] = (uint8_t)buffer[i];
    if (int_list(ring12, buffer, size * 12, "ring12") < 0)
        return NULL;
    for (int i = 0; i < size * 12; i++)
        d->ring12[i / 12][i % 12] = (uint8_t)buffer[i];
    PyObject *fast = PySequence_Fast(near, "near");
    if (!fast)
        return NULL;
    if (PySequence_Fast_GET_SIZE(fast) != size) {
        Py_DECREF(fast);
        PyErr_SetString(PyExc_ValueError, "near: one mask per window cell expected");
        return NULL;
    }
    for (int i = 0; i < size; i++) {
        d->near[i] = PyLong_AsUnsignedLongLong(PySequence_Fast_GET_ITEM(fast, i));
        if (PyErr_Occurred()) {
            Py_DECREF(fast);
            return NULL;
        }
    }
    Py_DECREF(fast);
    if (int_list(goal_index, buffer, size * goals, "goal_index") < 0)
        return NULL;
    for (int i = 0; i < size; i++)
        for (int g = 0; g < MAX_GOALS; g++)
            d->goal_index[i][g] = (int8_t)(g < goals ? buffer[i * goals + g] : -1);
    return PyLong_FromLong(disc_count++);
}

static PyMethodDef methods[] = {
    {"search", search, METH_VARARGS,
     "search(disc, start, outside_lo, outside_hi, pinned, nearer, max_states)"
     " -> ([(mover, target, mask, option), ...], arrived) or None"},
    {"set_rules", set_rules, METH_VARARGS, "set_rules(leavable, open_goals)"},
    {"add_disc", add_disc, METH_VARARGS, "add_disc(size, ncells, center, ring6, ring12, near,"
     " goal_index, goals) -> disc id"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_crossing",
    "A* of a journey's crossing over bit-mask window states (journey.crossing).", -1, methods,
};

PyMODINIT_FUNC PyInit__crossing(void)
{
    return PyModule_Create(&module);
}
