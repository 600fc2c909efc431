/*
 * hexbot.planning._schedule: the list schedule of schedule.schedule_parallel,
 * in C.
 *
 * The strip plans of 10,000 modules have 5-6 million moves, and the Python
 * schedule took about 10 us a move (the scramble of 10,000: 69 s of 115 s of
 * planning, after the strip itself went to C). This is the same schedule,
 * step for step (tests/planning/test_planning_schedule.py compares it with
 * the Python reference): the same dependency graph over the same window of
 * unscheduled moves, the same ready order (longest chain to the end first
 * in the fine schedule, serial order in the coarse one), the same test that
 * a mover is no cut vertex of what stays.
 *
 * No geometry lives here: schedule.py hands over, once, the six sides, the
 * one-arc table of a ring of neighbours, and each rotation's (joint,
 * direction) with the offsets of its goal and swept cells. A schedule gets
 * the initial cells, the serial moves (read through their attributes) and
 * the deadline, whose check() it calls as the Python schedule did.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define SIDES 6
#define MAX_RULES 16
/* Cells of the plan stay this far inside the grid: swept cells lie within two
 * cells of a move's start, and the connectivity test looks at neighbours. */
#define MARGIN 4
#define DEADLINE_EVERY 256

static int side_dx[SIDES], side_dy[SIDES];
static uint8_t one_arc[64];
static int rule_count;
static long rule_joint[MAX_RULES];
static PyObject *rule_direction[MAX_RULES];
static int rule_off[MAX_RULES][10];  /* goal, swept a, b, c, substrate: (dx, dy) each */
static int rules_set;
static PyObject *s_module, *s_src, *s_joint, *s_direction, *s_substrate, *s_check, *s_what;

/* set_rules(sides, one_arc, rotations): sides = 6 (dx, dy) in side order;
 * one_arc = 64 booleans; rotations = (joint, direction, (goal, a, b, c offsets
 * flattened: 8 ints), (substrate dx, dy)). */
static PyObject *set_rules(PyObject *self, PyObject *args)
{
    PyObject *sides, *arcs, *rotations;
    if (!PyArg_ParseTuple(args, "OOO", &sides, &arcs, &rotations))
        return NULL;
    PyObject *s = PySequence_Fast(sides, "sides"), *a = NULL, *r = NULL;
    if (!s)
        return NULL;
    a = PySequence_Fast(arcs, "one_arc");
    r = a ? PySequence_Fast(rotations, "rotations") : NULL;
    if (!r)
        goto fail;
    Py_ssize_t nr = PySequence_Fast_GET_SIZE(r);
    if (PySequence_Fast_GET_SIZE(s) != SIDES || PySequence_Fast_GET_SIZE(a) != 64
        || nr < 1 || nr > MAX_RULES) {
        PyErr_SetString(PyExc_ValueError, "set_rules: 6 sides, 64 arcs, 1-16 rotations");
        goto fail;
    }
    for (int i = 0; i < SIDES; i++)
        if (!PyArg_ParseTuple(PySequence_Fast_GET_ITEM(s, i), "ii", &side_dx[i], &side_dy[i]))
            goto fail;
    for (int i = 0; i < 64; i++) {
        int truth = PyObject_IsTrue(PySequence_Fast_GET_ITEM(a, i));
        if (truth < 0)
            goto fail;
        one_arc[i] = (uint8_t)truth;
    }
    for (int i = 0; i < nr; i++) {
        PyObject *direction;
        int *o = rule_off[i];
        if (!PyArg_ParseTuple(PySequence_Fast_GET_ITEM(r, i), "lO(iiiiiiii)(ii)", &rule_joint[i],
                              &direction, &o[0], &o[1], &o[2], &o[3], &o[4], &o[5], &o[6],
                              &o[7], &o[8], &o[9]))
            goto fail;
        Py_XSETREF(rule_direction[i], Py_NewRef(direction));
    }
    rule_count = (int)nr;
    rules_set = 1;
    Py_DECREF(s), Py_DECREF(a), Py_DECREF(r);
    Py_RETURN_NONE;
fail:
    Py_XDECREF(s), Py_XDECREF(a), Py_XDECREF(r);
    return NULL;
}

/* ---- small containers --------------------------------------------------- */

typedef struct { int32_t *at; size_t size, cap; } Vec;

static int vec_push(Vec *v, int32_t x)
{
    if (v->size == v->cap) {
        size_t cap = v->cap ? 2 * v->cap : 64;
        int32_t *at = realloc(v->at, cap * sizeof *at);
        if (!at)
            return -1;
        v->at = at, v->cap = cap;
    }
    v->at[v->size++] = x;
    return 0;
}

/* Singly linked lists of move indices in one pool, nodes reused once released. */
typedef struct { int32_t move, next; } Node;
typedef struct { Node *at; int32_t size, cap, free; } Pool;

static int pool_push(Pool *p, int32_t *head, int32_t move)
{
    int32_t i = p->free;
    if (i >= 0) {
        p->free = p->at[i].next;
    } else {
        if (p->size == p->cap) {
            int32_t cap = p->cap ? 2 * p->cap : 1024;
            Node *at = realloc(p->at, (size_t)cap * sizeof *at);
            if (!at)
                return -1;
            p->at = at, p->cap = cap;
        }
        i = p->size++;
    }
    p->at[i].move = move, p->at[i].next = *head;
    *head = i;
    return 0;
}

static void pool_release(Pool *p, int32_t head)
{
    while (head >= 0) {
        int32_t next = p->at[head].next;
        p->at[head].next = p->free;
        p->free = head;
        head = next;
    }
}

typedef struct { int64_t *at; size_t size, cap; } Heap;

static int keys_room(Heap *h)
{
    if (h->size < h->cap)
        return 0;
    size_t cap = h->cap ? 2 * h->cap : 1024;
    int64_t *at = realloc(h->at, cap * sizeof *at);
    if (!at)
        return -1;
    h->at = at, h->cap = cap;
    return 0;
}

static int keys_push(Heap *h, int64_t key)
{
    if (keys_room(h) < 0)
        return -1;
    h->at[h->size++] = key;
    return 0;
}

static int heap_push(Heap *h, int64_t key)
{
    if (keys_room(h) < 0)
        return -1;
    size_t i = h->size++;
    while (i) {
        size_t up = (i - 1) / 2;
        if (h->at[up] <= key)
            break;
        h->at[i] = h->at[up];
        i = up;
    }
    h->at[i] = key;
    return 0;
}

static int64_t heap_pop(Heap *h)
{
    int64_t top = h->at[0], last = h->at[--h->size];
    size_t i = 0, n = h->size;
    for (;;) {
        size_t child = 2 * i + 1;
        if (child >= n)
            break;
        if (child + 1 < n && h->at[child + 1] < h->at[child])
            child++;
        if (h->at[child] >= last)
            break;
        h->at[i] = h->at[child];
        i = child;
    }
    if (n)
        h->at[i] = last;
    return top;
}

/* Module ids -> dense indices (open addressing). */
typedef struct { int64_t *keys; int32_t *values; uint8_t *used; size_t cap, count; } IdMap;

static size_t id_slot(const IdMap *m, int64_t key)
{
    uint64_t h = (uint64_t)key * 0x9E3779B97F4A7C15ull;
    size_t i = (size_t)(h >> 17) & (m->cap - 1);
    while (m->used[i] && m->keys[i] != key)
        i = (i + 1) & (m->cap - 1);
    return i;
}

static int id_grow(IdMap *m)
{
    IdMap old = *m;
    m->cap = old.cap ? 2 * old.cap : 1024;
    m->keys = malloc(m->cap * sizeof *m->keys);
    m->values = malloc(m->cap * sizeof *m->values);
    m->used = calloc(m->cap, 1);
    if (!m->keys || !m->values || !m->used) {
        free(m->keys), free(m->values), free(m->used);
        *m = old;
        return -1;
    }
    for (size_t i = 0; i < old.cap; i++)
        if (old.used[i]) {
            size_t j = id_slot(m, old.keys[i]);
            m->used[j] = 1, m->keys[j] = old.keys[i], m->values[j] = old.values[i];
        }
    free(old.keys), free(old.values), free(old.used);
    return 0;
}

/* The index of `key`, a new one when it is new; -1 when out of memory. */
static int32_t id_index(IdMap *m, int64_t key)
{
    if (2 * (m->count + 1) > m->cap && id_grow(m) < 0)
        return -1;
    size_t i = id_slot(m, key);
    if (!m->used[i]) {
        m->used[i] = 1, m->keys[i] = key, m->values[i] = (int32_t)m->count++;
    }
    return m->values[i];
}

/* ---- the schedule ------------------------------------------------------- */

typedef struct {
    Py_ssize_t total;
    int fine;
    long xmin, ymin, w, h;
    int side_d[SIDES], goal_d[MAX_RULES], swept_d[MAX_RULES][3], sub_d[MAX_RULES];
    /* per move */
    int32_t *src, *mod, *waiting, *after, *level;  /* substrate: src + sub_d[rule] */
    uint8_t *rule, *done;
    /* per cell */
    uint8_t *occ;
    int32_t *last_change, *readers, *owner;
    uint32_t *busy, *owned;
    uint32_t busy_stamp, owner_stamp;
    /* per module */
    int32_t *last_of;
    Pool pool;
    Heap ready, held;  /* held: keys put back after the step (a plain array) */
    Vec deps, chosen, frontier[SIDES];
    size_t frontier_head[SIDES];
} Schedule;

static void schedule_free(Schedule *s)
{
    free(s->src), free(s->mod), free(s->waiting), free(s->after);
    free(s->level), free(s->rule), free(s->done), free(s->occ), free(s->last_change);
    free(s->readers), free(s->owner), free(s->busy), free(s->owned), free(s->last_of);
    free(s->pool.at), free(s->ready.at), free(s->held.at), free(s->deps.at), free(s->chosen.at);
    for (int i = 0; i < SIDES; i++)
        free(s->frontier[i].at);
}

static int read_cell(PyObject *cell, long *x, long *y)
{
    if (!PyTuple_Check(cell) || PyTuple_GET_SIZE(cell) != 2) {
        PyErr_SetString(PyExc_TypeError, "a cell is an (x, y) tuple");
        return -1;
    }
    *x = PyLong_AsLong(PyTuple_GET_ITEM(cell, 0));
    *y = PyLong_AsLong(PyTuple_GET_ITEM(cell, 1));
    return PyErr_Occurred() ? -1 : 0;
}

static inline int32_t at(const Schedule *s, long x, long y)
{
    return (int32_t)((y - s->ymin) * s->w + (x - s->xmin));
}

/* A move's fields: cells (x, y of src and substrate), module id, rotation. */
typedef struct { long sx, sy, bx, by; int64_t module; int rule; } Fields;

static int read_move(PyObject *move, Fields *f)
{
    PyObject *src = PyObject_GetAttr(move, s_src), *sub = PyObject_GetAttr(move, s_substrate);
    PyObject *module = PyObject_GetAttr(move, s_module), *joint = PyObject_GetAttr(move, s_joint);
    PyObject *direction = PyObject_GetAttr(move, s_direction);
    int ok = src && sub && module && joint && direction && read_cell(src, &f->sx, &f->sy) == 0
        && read_cell(sub, &f->bx, &f->by) == 0;
    if (ok) {
        f->module = PyLong_AsLongLong(module);
        long j = PyLong_AsLong(joint);
        ok = !PyErr_Occurred();
        f->rule = -1;
        for (int r = 0; ok && r < rule_count && f->rule < 0; r++)
            if (rule_joint[r] == j && rule_direction[r] == direction)
                f->rule = r;
        /* not the rotation's own object (a plan read back from a file): compare */
        for (int r = 0; ok && r < rule_count && f->rule < 0; r++)
            if (rule_joint[r] == j) {
                int same = PyObject_RichCompareBool(rule_direction[r], direction, Py_EQ);
                if (same < 0)
                    ok = 0;
                else if (same)
                    f->rule = r;
            }
        if (ok && f->rule < 0) {
            PyErr_Format(PyExc_ValueError, "no rotation about joint %ld %R", j, direction);
            ok = 0;
        }
    }
    Py_XDECREF(src), Py_XDECREF(sub), Py_XDECREF(module), Py_XDECREF(joint);
    Py_XDECREF(direction);
    return ok ? 0 : -1;
}

static inline void extend(long box[4], long x, long y)
{
    if (x < box[0])
        box[0] = x;
    if (y < box[1])
        box[1] = y;
    if (x > box[2])
        box[2] = x;
    if (y > box[3])
        box[3] = y;
}

static inline int64_t key_of(const Schedule *s, int32_t k)
{
    return s->fine ? (int64_t)k - (int64_t)s->level[k] * s->total : k;
}

static inline int32_t move_of(const Schedule *s, int64_t key)
{
    int64_t k = key % s->total;
    return (int32_t)(k < 0 ? k + s->total : k);
}

/* Is the occupied set without `cell` still one piece? The neighbours in one
 * arc settle it; else a search from each, taking turns, merging where they
 * meet, until one runs dry (cut) or one is left (connected). */
static int stays_connected(Schedule *s, int32_t cell)
{
    int mask = 0;
    for (int i = 0; i < SIDES; i++)
        if (s->occ[cell + s->side_d[i]])
            mask |= 1 << i;
    if (one_arc[mask])
        return 1;
    if (++s->owner_stamp == 0) {
        memset(s->owned, 0, (size_t)s->w * s->h * sizeof *s->owned);
        s->owner_stamp = 1;
    }
    uint32_t stamp = s->owner_stamp;
    int label[SIDES], alive[SIDES], seeds = 0, left = 0;
    s->owned[cell] = stamp, s->owner[cell] = -1;
    for (int i = 0; i < SIDES; i++) {
        if (!(mask >> i & 1))
            continue;
        int32_t n = cell + s->side_d[i];
        s->owned[n] = stamp, s->owner[n] = seeds;
        s->frontier[seeds].size = 0, s->frontier_head[seeds] = 0;
        if (vec_push(&s->frontier[seeds], n) < 0)
            return -1;
        label[seeds] = seeds, alive[seeds] = 1;
        seeds++, left++;
    }
    for (;;) {
        for (int i = 0; i < seeds; i++) {
            if (!alive[i])
                continue;
            Vec *q = &s->frontier[i];
            if (s->frontier_head[i] == q->size)
                return 0;  /* ran dry before meeting the others: a piece is cut off */
            int32_t c = q->at[s->frontier_head[i]++];
            for (int d = 0; d < SIDES; d++) {
                int32_t n = c + s->side_d[d];
                if (!s->occ[n])
                    continue;
                if (s->owned[n] != stamp) {
                    s->owned[n] = stamp, s->owner[n] = i;
                    if (vec_push(q, n) < 0)
                        return -1;
                    continue;
                }
                int other = s->owner[n];
                if (other < 0)
                    continue;
                while (label[other] != other)
                    other = label[other];
                if (other == i)
                    continue;
                label[other] = i, alive[other] = 0;
                Vec *o = &s->frontier[other];
                for (size_t j = s->frontier_head[other]; j < o->size; j++)
                    if (vec_push(q, o->at[j]) < 0)
                        return -1;
                if (--left == 1)
                    return 1;
            }
        }
    }
}

/* For each move, the longest chain of dependent moves from it to the end of the
 * plan in the fine graph (schedule.bottom_levels). */
static void bottom_levels(Schedule *s, int32_t *next_of)
{
    size_t cells = (size_t)s->w * s->h;
    int32_t *next_change = s->last_change, *readers = s->readers;  /* reused, reset after */
    memset(next_change, 0, cells * sizeof *next_change);
    memset(readers, 0, cells * sizeof *readers);
    for (Py_ssize_t k = s->total - 1; k >= 0; k--) {
        int32_t src = s->src[k], dst = src + s->goal_d[s->rule[k]];
        int32_t reads[4] = {src + s->sub_d[s->rule[k]], src + s->swept_d[s->rule[k]][0],
                            src + s->swept_d[s->rule[k]][1], src + s->swept_d[s->rule[k]][2]};
        int32_t level = next_of[s->mod[k]];
        for (int i = 0; i < 4; i++)
            if (next_change[reads[i]] > level)
                level = next_change[reads[i]];
        int32_t around[4] = {next_change[src], readers[src], next_change[dst], readers[dst]};
        for (int i = 0; i < 4; i++)
            if (around[i] > level)
                level = around[i];
        level += 1;
        s->level[k] = level;
        next_of[s->mod[k]] = level;
        for (int i = 0; i < 4; i++)
            if (readers[reads[i]] < level)
                readers[reads[i]] = level;
        next_change[src] = next_change[dst] = level;
        readers[src] = readers[dst] = 0;
    }
}

static PyObject *fail_schedule(Schedule *s, PyObject *steps)
{
    schedule_free(s);
    Py_XDECREF(steps);
    return NULL;
}

/* schedule(initial cells, serial moves, fine, window, deadline) -> [[Move]] or None */
static PyObject *schedule(PyObject *self, PyObject *args)
{
    PyObject *initial, *serial, *deadline;
    int fine;
    Py_ssize_t window;
    if (!PyArg_ParseTuple(args, "OO!pnO", &initial, &PyList_Type, &serial, &fine, &window,
                          &deadline))
        return NULL;
    if (!rules_set) {
        PyErr_SetString(PyExc_RuntimeError, "schedule: set_rules() first");
        return NULL;
    }
    Schedule s = {0};
    IdMap ids = {0};
    PyObject *steps = NULL;
    s.total = PyList_GET_SIZE(serial), s.fine = fine;
    if (s.total >= INT32_MAX / 2) {
        PyErr_SetString(PyExc_ValueError, "schedule: too many moves");
        return NULL;
    }
    PyObject *cells = PySequence_Fast(initial, "initial cells");
    if (!cells)
        return NULL;
    Py_ssize_t ncells = PySequence_Fast_GET_SIZE(cells);
    if (ncells == 0) {
        Py_DECREF(cells);
        PyErr_SetString(PyExc_ValueError, "schedule: no initial cells");
        return NULL;
    }
    /* First pass: each move's fields, its start as (x, y) held for now in the
     * per-move arrays src and after, and the extent of every cell the plan
     * uses. */
    size_t nmove = (size_t)s.total + 1;
    s.src = malloc(nmove * sizeof *s.src);
    s.mod = malloc(nmove * sizeof *s.mod), s.waiting = malloc(nmove * sizeof *s.waiting);
    s.after = malloc(nmove * sizeof *s.after), s.rule = malloc(nmove);
    s.done = calloc(nmove, 1), s.level = fine ? malloc(nmove * sizeof *s.level) : NULL;
    s.pool.free = -1;
    if (!s.src || !s.mod || !s.waiting || !s.after || !s.rule || !s.done
        || (fine && !s.level)) {
        PyErr_NoMemory();
        goto early;
    }
    long box[4] = {LONG_MAX, LONG_MAX, LONG_MIN, LONG_MIN}, x, y;  /* xmin, ymin, xmax, ymax */
    for (Py_ssize_t i = 0; i < ncells; i++) {
        if (read_cell(PySequence_Fast_GET_ITEM(cells, i), &x, &y) < 0)
            goto early;
        extend(box, x, y);
    }
    for (Py_ssize_t k = 0; k < s.total; k++) {
        Fields f;
        if (read_move(PyList_GET_ITEM(serial, k), &f) < 0)
            goto early;
        if (f.sx < -(1L << 20) || f.sx > 1L << 20 || f.sy < -(1L << 20) || f.sy > 1L << 20
            || f.bx < -(1L << 20) || f.bx > 1L << 20 || f.by < -(1L << 20) || f.by > 1L << 20) {
            PyErr_SetString(PyExc_ValueError, "schedule: a cell is out of range");
            goto early;
        }
        extend(box, f.sx, f.sy);
        extend(box, f.bx, f.by);
        if (f.bx != f.sx + rule_off[f.rule][8] || f.by != f.sy + rule_off[f.rule][9]) {
            PyErr_Format(PyExc_ValueError, "schedule: move %zd pivots on (%ld, %ld), not on"
                         " its rotation's substrate", k, f.bx, f.by);
            goto early;
        }
        s.src[k] = (int32_t)f.sx, s.after[k] = (int32_t)f.sy;
        s.rule[k] = (uint8_t)f.rule;
        if ((s.mod[k] = id_index(&ids, f.module)) < 0) {
            PyErr_NoMemory();
            goto early;
        }
    }
    s.xmin = box[0] - MARGIN, s.ymin = box[1] - MARGIN;
    s.w = box[2] - s.xmin + MARGIN + 1, s.h = box[3] - s.ymin + MARGIN + 1;
    if ((long long)s.w * s.h > 1LL << 30) {
        PyErr_SetString(PyExc_ValueError, "schedule: the plan spans too many cells");
        goto early;
    }
    size_t ncell = (size_t)s.w * s.h, modules = ids.count + 1;
    for (int i = 0; i < SIDES; i++)
        s.side_d[i] = (int)(side_dy[i] * s.w + side_dx[i]);
    for (int r = 0; r < rule_count; r++) {
        s.goal_d[r] = (int)(rule_off[r][1] * s.w + rule_off[r][0]);
        s.sub_d[r] = (int)(rule_off[r][9] * s.w + rule_off[r][8]);
        for (int j = 0; j < 3; j++)
            s.swept_d[r][j] = (int)(rule_off[r][3 + 2 * j] * s.w + rule_off[r][2 + 2 * j]);
    }
    for (Py_ssize_t k = 0; k < s.total; k++) {
        s.src[k] = at(&s, s.src[k], s.after[k]);
        s.waiting[k] = 0, s.after[k] = -1;
    }
    free(ids.keys), free(ids.values), free(ids.used);
    ids = (IdMap){0};
    s.occ = calloc(ncell, 1), s.last_change = malloc(ncell * sizeof *s.last_change);
    s.readers = malloc(ncell * sizeof *s.readers), s.owner = malloc(ncell * sizeof *s.owner);
    s.busy = calloc(ncell, sizeof *s.busy), s.owned = calloc(ncell, sizeof *s.owned);
    s.last_of = calloc(modules, sizeof *s.last_of);
    if (!s.occ || !s.last_change || !s.readers || !s.owner || !s.busy || !s.owned
        || !s.last_of) {
        PyErr_NoMemory();
        goto early;
    }
    for (Py_ssize_t i = 0; i < ncells; i++) {
        read_cell(PySequence_Fast_GET_ITEM(cells, i), &x, &y);
        s.occ[at(&s, x, y)] = 1;
    }
    Py_DECREF(cells), cells = NULL;
    if (fine)
        bottom_levels(&s, s.last_of);  /* last_of: the next level of each module, from 0 */
    for (size_t i = 0; i < ncell; i++)
        s.last_change[i] = -1, s.readers[i] = -1;
    for (size_t i = 0; i < modules; i++)
        s.last_of[i] = -1;
    if (!(steps = PyList_New(0)))
        return fail_schedule(&s, NULL);

    Py_ssize_t admitted = 0, waiting = 0;
    while (admitted < s.total || s.ready.size || waiting) {
        /* admit moves into the graph */
        while (admitted < s.total && (Py_ssize_t)(waiting + s.ready.size) < window) {
            int32_t k = (int32_t)admitted++;
            int32_t src = s.src[k], r = s.rule[k], dst = src + s.goal_d[r];
            int32_t a = src + s.swept_d[r][0], b = src + s.swept_d[r][1];
            int32_t c = src + s.swept_d[r][2];
            int32_t reads[4] = {src + s.sub_d[r], a, b, c}, changes[5] = {src, dst, a, b, c};
            int nreads = fine ? 4 : 1, nchanges = fine ? 2 : 5;
            s.deps.size = 0;
            int32_t j = s.last_of[s.mod[k]];
            if (j >= 0 && !s.done[j] && vec_push(&s.deps, j) < 0)
                goto oom;
            for (int i = 0; i < nreads; i++) {
                j = s.last_change[reads[i]];
                if (j >= 0 && !s.done[j] && vec_push(&s.deps, j) < 0)
                    goto oom;
                if (pool_push(&s.pool, &s.readers[reads[i]], k) < 0)
                    goto oom;
            }
            for (int i = 0; i < nchanges; i++) {
                j = s.last_change[changes[i]];
                if (j >= 0 && !s.done[j] && vec_push(&s.deps, j) < 0)
                    goto oom;
                int32_t head = s.readers[changes[i]];
                for (int32_t n = head; n >= 0; n = s.pool.at[n].next)
                    if (!s.done[s.pool.at[n].move] && vec_push(&s.deps, s.pool.at[n].move) < 0)
                        goto oom;
                pool_release(&s.pool, head);
                s.readers[changes[i]] = -1;
                s.last_change[changes[i]] = k;
            }
            s.last_of[s.mod[k]] = k;
            if (s.deps.size) {
                for (size_t i = 0; i < s.deps.size; i++)
                    if (pool_push(&s.pool, &s.after[s.deps.at[i]], k) < 0)
                        goto oom;
                s.waiting[k] = (int32_t)s.deps.size;
                waiting++;
            } else if (heap_push(&s.ready, key_of(&s, k)) < 0) {
                goto oom;
            }
        }
        if (PyList_GET_SIZE(steps) % DEADLINE_EVERY == 0) {
            PyObject *ok = PyObject_CallMethodOneArg(deadline, s_check, s_what);
            if (!ok)
                return fail_schedule(&s, steps);
            Py_DECREF(ok);
        }
        s.chosen.size = s.held.size = 0;
        if (++s.busy_stamp == 0) {
            memset(s.busy, 0, ncell * sizeof *s.busy);
            s.busy_stamp = 1;
        }
        while (s.ready.size) {
            int64_t key = heap_pop(&s.ready);
            int32_t k = move_of(&s, key), src = s.src[k], r = s.rule[k];
            int32_t around[5] = {src, src + s.goal_d[r], src + s.swept_d[r][0],
                                 src + s.swept_d[r][1], src + s.swept_d[r][2]};
            if (fine) {  /* reads keep no order: a cell may not serve two moves of a step */
                int busy = 0;
                for (int i = 0; i < 5; i++)
                    busy |= s.busy[around[i]] == s.busy_stamp;
                if (busy) {
                    if (keys_push(&s.held, key) < 0)
                        goto oom;
                    continue;
                }
            }
            int connected = stays_connected(&s, src);
            if (connected < 0)
                goto oom;
            if (!connected) {
                if (keys_push(&s.held, key) < 0)
                    goto oom;
                continue;
            }
            s.occ[src] = 0;  /* the rest of the step sees what stays put */
            if (fine)
                for (int i = 0; i < 5; i++)
                    s.busy[around[i]] = s.busy_stamp;
            if (vec_push(&s.chosen, k) < 0)
                goto oom;
        }
        if (!s.chosen.size) {  /* stuck: every ready move is a cut vertex */
            schedule_free(&s);
            Py_DECREF(steps);
            Py_RETURN_NONE;
        }
        for (size_t i = 0; i < s.held.size; i++)
            if (heap_push(&s.ready, s.held.at[i]) < 0)
                goto oom;
        PyObject *step = PyList_New((Py_ssize_t)s.chosen.size);
        if (!step)
            return fail_schedule(&s, steps);
        for (size_t i = 0; i < s.chosen.size; i++) {
            int32_t k = s.chosen.at[i];
            s.occ[s.src[k] + s.goal_d[s.rule[k]]] = 1;
            s.done[k] = 1;
            PyList_SET_ITEM(step, (Py_ssize_t)i, Py_NewRef(PyList_GET_ITEM(serial, k)));
        }
        int appended = PyList_Append(steps, step);
        Py_DECREF(step);
        if (appended < 0)
            return fail_schedule(&s, steps);
        for (size_t i = 0; i < s.chosen.size; i++) {
            int32_t k = s.chosen.at[i], head = s.after[k];
            for (int32_t n = head; n >= 0; n = s.pool.at[n].next) {
                int32_t j = s.pool.at[n].move;
                if (--s.waiting[j] == 0) {
                    waiting--;
                    if (heap_push(&s.ready, key_of(&s, j)) < 0)
                        goto oom;
                }
            }
            pool_release(&s.pool, head);
            s.after[k] = -1;
        }
    }
    schedule_free(&s);
    return steps;
oom:
    PyErr_NoMemory();
    return fail_schedule(&s, steps);
early:
    Py_XDECREF(cells);
    free(ids.keys), free(ids.values), free(ids.used);
    return fail_schedule(&s, NULL);
}

static PyMethodDef methods[] = {
    {"set_rules", set_rules, METH_VARARGS, "set_rules(sides, one_arc, rotations)"},
    {"schedule", schedule, METH_VARARGS,
     "schedule(initial cells, serial moves, fine, window, deadline) -> [[Move]] or None"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_schedule",
    "The list schedule of a serial plan (schedule.schedule_parallel), in C.", -1, methods,
};

PyMODINIT_FUNC PyInit__schedule(void)
{
    s_module = PyUnicode_InternFromString("module");
    s_src = PyUnicode_InternFromString("src");
    s_joint = PyUnicode_InternFromString("joint");
    s_direction = PyUnicode_InternFromString("direction");
    s_substrate = PyUnicode_InternFromString("substrate");
    s_check = PyUnicode_InternFromString("check");
    s_what = PyUnicode_InternFromString("parallel schedule");
    if (!s_module || !s_src || !s_joint || !s_direction || !s_substrate || !s_check || !s_what)
        return NULL;
    return PyModule_Create(&module);
}
