/*
 * hexbot.planning._tidy: one pass of tidy.shorten (detours cut short), in C.
 *
 * The pass walks the serial plan; at each move of a module it replays the
 * other modules' later moves with that module kept home, and where the
 * module could roll to a cell it reaches later in fewer rotations than it
 * made, the roll replaces its moves. In Python that replay cost about 2 s a
 * pass on the blobs of 1,000 (5,000-6,000 moves), so plans of more than
 * 3,000 moves were left untidied until session 18. Here the same pass runs
 * over a grid of module numbers, in the same order, so it makes the same
 * plan, move for move (tests/planning/test_planning_tidy.py compares it with
 * the Python pass kept in tests/planning/tidy_reference.py).
 *
 * No geometry lives here: tidy.py hands over, once, the 12 cells around a
 * mobile module, the Table 4-3 rotations (substrate bit, goal and swept
 * bits, substrate and goal offsets) in ROTATIONS order, the six sides and
 * the one-arc table of a ring of neighbours; and with each pass the
 * lattice distance of every offset of its grid.
 */
#include "_rules.h"
#include <stdlib.h>
#include <string.h>

#define DEADLINE_EVERY 64
#define one_arc ring_table /* set_rules' table: are the occupied sides one arc? */

/* One move of the plan: its module and substrate module as numbers from 1,
 * its start as a grid index, its rotation, and where it came from (its index
 * in the plan handed over, or -1 for a roll made by this pass). */
typedef struct {
    int32_t module, src, rot, sub, origin;
} Entry;

typedef struct {
    int w, h;
    size_t cells;
    int32_t *where;             /* module number + 1 on each cell, 0 = empty */
    const int32_t *dist;        /* lattice distance by offset (see distance()) */
    uint32_t *seen, stamp;
    int32_t *queue, *parent, *depth;
    int8_t *rule;
    int ring_d[RING], side_d[SIDES], sub_d[MAX_RULES], goal_d[MAX_RULES];
    Entry *plan;
    Py_ssize_t n;
    int32_t *next_own, *last_own; /* next move of the same module (-1: none) */
    int32_t modules;
    int32_t *log;                 /* moves applied by a replay, to take back */
    Entry *roll, *best, *spare;   /* the roll just found, the best one so far */
    int32_t roll_len, best_len;
} Pass;

static void pass_free(Pass *p)
{
    free(p->seen), free(p->queue), free(p->parent), free(p->depth), free(p->rule);
    free(p->plan), free(p->next_own), free(p->last_own), free(p->log);
    free(p->roll), free(p->best), free(p->spare);
}

/* set_rules(ring, rotations, sides, one_arc): see _rules.h; one_arc = 64
 * booleans (bit i of a mask: side i occupied). */
static PyObject *set_rules(PyObject *self, PyObject *args)
{
    return read_rules(args, "one_arc");
}

static inline int32_t distance(const Pass *p, int32_t a, int32_t b)
{
    return grid_distance(p->dist, p->w, p->h, a, b);
}

static inline unsigned ring_mask(const Pass *p, int32_t i)
{
    unsigned mask = 0;
    for (int b = 0; b < RING; b++)
        if (p->where[i + p->ring_d[b]])
            mask |= 1u << b;
    return mask;
}

static inline uint32_t next_stamp(Pass *p)
{
    if (++p->stamp == 0) {  /* wrapped: forget every mark once */
        memset(p->seen, 0, p->cells * sizeof *p->seen);
        p->stamp = 1;
    }
    return p->stamp;
}

/* Is the configuration without `cell` still one piece? One arc of occupied
 * neighbours is enough; otherwise a search from the first reaches the others. */
static int stays_connected(Pass *p, int32_t cell)
{
    int mask = 0, seeds = 0;
    for (int i = 0; i < SIDES; i++)
        if (p->where[cell + p->side_d[i]])
            mask |= 1 << i, seeds++;
    if (one_arc[mask])
        return 1;
    uint32_t stamp = next_stamp(p);
    p->seen[cell] = stamp;
    int32_t head = 0, tail = 0;
    for (int i = 0; i < SIDES && !tail; i++)
        if (mask >> i & 1) {
            int32_t first = cell + p->side_d[i];
            p->seen[first] = stamp;
            p->queue[tail++] = first;
        }
    int left = seeds - 1;
    while (head < tail) {
        int32_t c = p->queue[head++];
        for (int d = 0; d < SIDES; d++) {
            int32_t n = c + p->side_d[d];
            if (!p->where[n] || p->seen[n] == stamp)
                continue;
            p->seen[n] = stamp;
            p->queue[tail++] = n;
            for (int i = 0; i < SIDES; i++)
                if (mask >> i & 1 && n == cell + p->side_d[i] && --left == 0)
                    return 1;
        }
    }
    return 0;
}

/* The fewest rotations (at most `limit`) taking the module at `home` to
 * `target` with the others fixed, into p->roll: its length, or -1 (also when
 * the module's leaving would split the rest). Breadth first, the rotations in
 * ROTATIONS order, as the reference's _roll. */
static int32_t roll(Pass *p, int32_t home, int32_t target, int32_t limit)
{
    p->roll_len = 0;
    if (home == target)
        return 0;
    if (limit < 1 || !stays_connected(p, home))
        return -1;
    uint32_t stamp = next_stamp(p);
    int32_t module = p->where[home];
    p->where[home] = 0;  /* the mover's own cell counts as empty */
    p->seen[home] = stamp, p->parent[home] = -1, p->depth[home] = 0;
    int32_t head = 0, tail = 0;
    p->queue[tail++] = home;
    int found = 0;
    while (head < tail && !found) {
        int32_t cell = p->queue[head++];
        if (p->depth[cell] == limit)
            continue;
        unsigned mask = ring_mask(p, cell);
        for (int r = 0; r < rule_count; r++) {
            if (!is_open(mask, r))
                continue;
            int32_t goal = cell + p->goal_d[r];
            if (p->seen[goal] == stamp)
                continue;
            p->seen[goal] = stamp;
            p->parent[goal] = cell, p->rule[goal] = (int8_t)r;
            p->depth[goal] = p->depth[cell] + 1;
            if (goal == target) {
                found = 1;
                break;
            }
            p->queue[tail++] = goal;
        }
    }
    p->where[home] = module;
    if (!found)
        return -1;
    int32_t length = p->depth[target];
    for (int32_t c = target, k = length - 1; k >= 0; c = p->parent[c], k--) {
        int32_t from = p->parent[c];
        int r = p->rule[c];
        p->roll[k] = (Entry){module, from, r, p->where[from + p->sub_d[r]], -1};
    }
    return p->roll_len = length;
}

static inline int32_t dst_of(const Pass *p, const Entry *e)
{
    return e->src + p->goal_d[e->rot];
}

static int legal(Pass *p, const Entry *e)
{
    return p->where[e->src] == e->module && p->where[e->src + p->sub_d[e->rot]] == e->sub
        && is_open(ring_mask(p, e->src), e->rot) && stays_connected(p, e->src);
}

static void link_own(Pass *p)
{
    for (int32_t m = 0; m <= p->modules; m++)
        p->last_own[m] = -1;
    for (Py_ssize_t k = p->n - 1; k >= 0; k--) {
        int32_t m = p->plan[k].module;
        p->next_own[k] = p->last_own[m];
        p->last_own[m] = (int32_t)k;
    }
}

/* The reference's _best_shortcut: the end of the module's moves replaced by the best
 * roll (into p->best), or -1. */
static Py_ssize_t best_shortcut(Pass *p, Py_ssize_t start, Py_ssize_t window)
{
    const Entry *first = &p->plan[start];
    int32_t module = first->module, home = first->src;
    /* No shortcut ends after the last move where the module has made more
     * rotations than its distance from home (no roll is shorter than the
     * distance): the replay stops there. The reference replays on to the
     * module's last move, finding nothing more. */
    Py_ssize_t furthest = -1;
    int32_t made = 0;
    for (Py_ssize_t k = start; k >= 0 && k < start + window; k = p->next_own[k]) {
        made++;
        if (distance(p, home, dst_of(p, &p->plan[k])) < made)
            furthest = k;
    }
    if (furthest < 0)
        return -1;
    Py_ssize_t applied = 0, best_end = -1;
    int32_t best_saving = 0;
    made = 0;
    for (Py_ssize_t k = start; k <= furthest; k++) {
        Entry *e = &p->plan[k];
        if (e->module == module) {
            made++;
            int32_t saving = best_end >= 0 ? best_saving : 0;
            int32_t to = dst_of(p, e);
            if (distance(p, home, to) < made - saving) {
                int32_t length = roll(p, home, to, made - saving - 1);
                if (length >= 0) {
                    best_saving = made - length, best_end = k;
                    Entry *swap = p->best;
                    p->best = p->roll, p->roll = swap;
                    p->best_len = length;
                }
            }
            continue;
        }
        if (!legal(p, e))
            break;
        p->where[dst_of(p, e)] = p->where[e->src];
        p->where[e->src] = 0;
        p->log[applied++] = (int32_t)k;
    }
    while (applied) {  /* back to the configuration before `start` */
        const Entry *e = &p->plan[p->log[--applied]];
        p->where[e->src] = p->where[dst_of(p, e)];
        p->where[dst_of(p, e)] = 0;
    }
    return best_end;
}

/* plan[start:end + 1] = the other modules' moves in it, then the best roll */
static void splice(Pass *p, Py_ssize_t start, Py_ssize_t end)
{
    int32_t module = p->plan[start].module;
    Py_ssize_t kept = 0;
    for (Py_ssize_t k = start; k < end; k++)
        if (p->plan[k].module != module)
            p->spare[kept++] = p->plan[k];
    Py_ssize_t size = kept + p->best_len, tail = p->n - end - 1;
    memcpy(p->plan + start, p->spare, (size_t)kept * sizeof(Entry));
    memcpy(p->plan + start + kept, p->best, (size_t)p->best_len * sizeof(Entry));
    memmove(p->plan + start + size, p->plan + end + 1, (size_t)tail * sizeof(Entry));
    p->n = start + size + tail;
}

static int read_ints(PyObject *obj, Py_buffer *view, Py_ssize_t count, const char *what)
{
    if (PyObject_GetBuffer(obj, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    if (view->itemsize != 4 || !view->format || strcmp(view->format, "i") != 0
        || view->len != count * 4) {
        PyErr_Format(PyExc_ValueError, "one_pass: %s must be %zd C ints", what, count);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

/* one_pass(width, height, where, plan, modules, distances, window, deadline) -> list
 *
 * where: width * height ints, the module number + 1 on each grid cell (0 =
 * empty), cell (x, y) at x + y * width; plan: 4 ints a move (module number
 * + 1, start, rotation, substrate module number + 1); modules: the largest
 * module number + 1; distances: (2 width - 1) * (2 height - 1) ints, the
 * lattice distance of the offset (dx, dy) at (dx + width - 1) + (dy + height
 * - 1) * (2 width - 1); window: tidy.WINDOW; deadline: its expired() is asked
 * every 64 moves, and the pass stops there when it says so.
 *
 * Returns the new plan: for each move, its index in `plan` when kept, or
 * (module + 1, start, rotation, substrate module + 1) for a move of a roll.
 * Cells of the plan and of its rolls must lie 4 cells inside the grid. */
static PyObject *one_pass(PyObject *self, PyObject *args)
{
    int w, h, modules;
    Py_ssize_t window;
    PyObject *where_obj, *plan_obj, *dist_obj, *deadline;
    if (!PyArg_ParseTuple(args, "iiOOiOnO", &w, &h, &where_obj, &plan_obj, &modules,
                          &dist_obj, &window, &deadline))
        return NULL;
    if (!rules_set) {
        PyErr_SetString(PyExc_RuntimeError, "one_pass: set_rules first");
        return NULL;
    }
    if (w < 9 || h < 9 || (size_t)w * h > 1u << 28 || modules < 1) {
        PyErr_SetString(PyExc_ValueError, "one_pass: a grid of at least 9 x 9 and modules");
        return NULL;
    }
    Py_buffer where_view, plan_view, dist_view;
    if (read_ints(where_obj, &where_view, (Py_ssize_t)w * h, "where") < 0)
        return NULL;
    if (PyObject_GetBuffer(plan_obj, &plan_view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0) {
        PyBuffer_Release(&where_view);
        return NULL;
    }
    Py_ssize_t n = plan_view.len / 16;
    PyBuffer_Release(&plan_view);
    if (read_ints(plan_obj, &plan_view, 4 * n, "plan") < 0) {
        PyBuffer_Release(&where_view);
        return NULL;
    }
    if (read_ints(dist_obj, &dist_view, (Py_ssize_t)(2 * w - 1) * (2 * h - 1),
                  "distances") < 0) {
        PyBuffer_Release(&where_view), PyBuffer_Release(&plan_view);
        return NULL;
    }
    Pass p = {.w = w, .h = h, .cells = (size_t)w * h, .dist = dist_view.buf,
              .modules = modules, .n = n};
    PyObject *result = NULL;
    p.where = malloc(p.cells * sizeof *p.where);
    p.seen = calloc(p.cells, sizeof *p.seen);
    p.queue = malloc(p.cells * sizeof *p.queue);
    p.parent = malloc(p.cells * sizeof *p.parent);
    p.depth = malloc(p.cells * sizeof *p.depth);
    p.rule = malloc(p.cells);
    p.plan = malloc((size_t)(n + 1) * sizeof *p.plan);
    p.next_own = malloc((size_t)(n + 1) * sizeof *p.next_own);
    p.last_own = malloc((size_t)(modules + 1) * sizeof *p.last_own);
    p.log = malloc((size_t)(n + 1) * sizeof *p.log);
    p.roll = malloc(p.cells * sizeof *p.roll);
    p.best = malloc(p.cells * sizeof *p.best);
    p.spare = malloc((size_t)(n + 1) * sizeof *p.spare);
    if (!p.where || !p.seen || !p.queue || !p.parent || !p.depth || !p.rule || !p.plan
        || !p.next_own || !p.last_own || !p.log || !p.roll || !p.best || !p.spare) {
        PyErr_NoMemory();
        goto done;
    }
    memcpy(p.where, where_view.buf, p.cells * sizeof *p.where);
    for (int i = 0; i < RING; i++)
        p.ring_d[i] = ring_dx[i] + ring_dy[i] * w;
    for (int i = 0; i < SIDES; i++)
        p.side_d[i] = side_dx[i] + side_dy[i] * w;
    for (int r = 0; r < rule_count; r++)
        p.sub_d[r] = rule_sx[r] + rule_sy[r] * w, p.goal_d[r] = rule_gx[r] + rule_gy[r] * w;
    const int32_t *raw = plan_view.buf;
    for (Py_ssize_t k = 0; k < n; k++) {
        Entry e = {raw[4 * k], raw[4 * k + 1], raw[4 * k + 2], raw[4 * k + 3], (int32_t)k};
        int32_t x = e.src % w, y = e.src / w;
        if (e.module < 1 || e.module > modules || e.sub < 1 || e.sub > modules
            || e.rot < 0 || e.rot >= rule_count || e.src < 0 || (size_t)e.src >= p.cells
            || x < 4 || x >= w - 4 || y < 4 || y >= h - 4) {
            PyErr_Format(PyExc_ValueError, "one_pass: move %zd is off the grid or "
                         "names no module or rotation", k);
            goto done;
        }
        p.plan[k] = e;
    }
    link_own(&p);
    for (Py_ssize_t i = 0; i < p.n;) {
        if (i % DEADLINE_EVERY == 0) {
            PyObject *expired = PyObject_CallMethod(deadline, "expired", NULL);
            int stop = expired ? PyObject_IsTrue(expired) : -1;
            Py_XDECREF(expired);
            if (stop < 0)
                goto done;
            if (stop)
                break;
        }
        Py_ssize_t end = best_shortcut(&p, i, window);
        if (end < 0) {
            const Entry *e = &p.plan[i];
            p.where[dst_of(&p, e)] = p.where[e->src];
            p.where[e->src] = 0;
            i++;
            continue;
        }
        splice(&p, i, end);
        link_own(&p);
    }
    result = PyList_New(p.n);
    if (!result)
        goto done;
    for (Py_ssize_t k = 0; k < p.n; k++) {
        const Entry *e = &p.plan[k];
        PyObject *item = e->origin >= 0 ? PyLong_FromLong(e->origin)
            : Py_BuildValue("(iiii)", e->module, e->src, e->rot, e->sub);
        if (!item) {
            Py_CLEAR(result);
            goto done;
        }
        PyList_SET_ITEM(result, k, item);
    }
done:
    pass_free(&p);
    PyBuffer_Release(&where_view), PyBuffer_Release(&plan_view), PyBuffer_Release(&dist_view);
    return result;
}

static PyMethodDef methods[] = {
    {"set_rules", set_rules, METH_VARARGS, "set_rules(ring, rotations, sides, one_arc)"},
    {"one_pass", one_pass, METH_VARARGS,
     "one_pass(width, height, where, plan, modules, distances, window, deadline) -> plan"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "hexbot.planning._tidy",
    "One pass of tidy.shorten (detours cut short) over a grid.", -1, methods,
};

PyMODINIT_FUNC PyInit__tidy(void)
{
    return PyModule_Create(&module);
}
