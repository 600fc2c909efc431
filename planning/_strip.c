/*
 * hexbot.planning._strip: the searches of the canonical strip route, in C.
 *
 * canonical.to_strip picks a mover for every strip cell: one search outward
 * from the cell, a scan of the modules (farthest first) for one whose first
 * rotation enters what that search reached, and a path search for it. At
 * 10,000 modules that scan and those searches were 3/4 of the strip's time
 * (the scramble of 10,000: 160 s of strip in 250 s of planning). Here the
 * same searches run over an occupancy grid, in the same order, so the paths
 * are the same, hop for hop (tests/planning/test_planning_strip.py compares
 * them with the Python reference).
 *
 * No geometry lives here: canonical.py hands over, once, the 12 cells around
 * a mobile module, the Table 4-3 rotations as (substrate bit, swept and goal
 * bits, substrate and goal offsets) in ROTATIONS order, and the 6 sides in
 * side order. A grid is a capsule owned by Python; the caller keeps it in
 * step with its set of occupied cells (two updates per module gathered).
 */
#include "_rules.h"
#include <stdlib.h>
#include <string.h>

/* Occupied cells and searched targets stay this far inside the grid's edge:
 * a searched cell touches a module, and the 12-cell ring reaches 2 cells
 * further, so no look-up leaves the grid. */
#define MARGIN 3


typedef struct {
    int xmin, ymin, w, h;
    uint8_t *occ;
    uint32_t *seen, *reach;      /* visit stamps of the path and the outward search */
    uint32_t stamp, reach_stamp;
    int32_t *parent, *queue, *dist; /* dist: rotations to the outward search's target */
    int32_t *disc, *low;         /* the cut-vertex pass */
    uint8_t *side, *cut;
    int8_t *rule;                /* rotation that reached a cell (path search) */
    int ring_d[RING], side_d[SIDES], sub_d[MAX_RULES], goal_d[MAX_RULES];
} Grid;

static const char *CAPSULE = "hexbot.planning._strip.grid";

static void release(Grid *g)
{
    free(g->occ), free(g->seen), free(g->reach), free(g->parent), free(g->queue);
    free(g->rule), free(g->dist), free(g->disc), free(g->low), free(g->side), free(g->cut);
    free(g);
}

static void grid_free(PyObject *capsule)
{
    Grid *g = PyCapsule_GetPointer(capsule, CAPSULE);
    if (g)
        release(g);
}

static Grid *grid_of(PyObject *capsule)
{
    return PyCapsule_GetPointer(capsule, CAPSULE);
}

static inline int inside(const Grid *g, long x, long y)
{
    return x >= g->xmin + MARGIN && x < g->xmin + g->w - MARGIN
        && y >= g->ymin + MARGIN && y < g->ymin + g->h - MARGIN;
}

static inline int32_t index_of(const Grid *g, long x, long y)
{
    return (int32_t)((y - g->ymin) * g->w + (x - g->xmin));
}

static PyObject *cell_at(const Grid *g, int32_t i)
{
    return Py_BuildValue("(ii)", i % g->w + g->xmin, i / g->w + g->ymin);
}

/* A cell given as (x, y), inside the margin; -1 with an exception otherwise. */
static int32_t cell_index(const Grid *g, PyObject *cell)
{
    if (!PyTuple_Check(cell) || PyTuple_GET_SIZE(cell) != 2) {
        PyErr_SetString(PyExc_TypeError, "a cell is an (x, y) tuple");
        return -1;
    }
    long x = PyLong_AsLong(PyTuple_GET_ITEM(cell, 0));
    long y = PyLong_AsLong(PyTuple_GET_ITEM(cell, 1));
    if (PyErr_Occurred())
        return -1;
    if (!inside(g, x, y)) {
        PyErr_Format(PyExc_ValueError, "cell (%ld, %ld) is outside the grid", x, y);
        return -1;
    }
    return index_of(g, x, y);
}

static inline unsigned ring_mask(const Grid *g, int32_t i)
{
    unsigned mask = 0;
    for (int b = 0; b < RING; b++)
        if (g->occ[i + g->ring_d[b]])
            mask |= 1u << b;
    return mask;
}

static inline void next_stamp(uint32_t *stamp, uint32_t *marks, size_t cells)
{
    if (++*stamp == 0) {  /* wrapped: forget every mark once */
        memset(marks, 0, cells * sizeof *marks);
        *stamp = 1;
    }
}

/* set_rules(ring, rotations, sides): see _rules.h (no table). */
static PyObject *set_rules(PyObject *self, PyObject *args)
{
    return read_rules(args, NULL);
}

/* grid(xmin, ymin, width, height) -> an empty grid */
static PyObject *grid_new(PyObject *self, PyObject *args)
{
    int xmin, ymin, w, h;
    if (!PyArg_ParseTuple(args, "iiii", &xmin, &ymin, &w, &h))
        return NULL;
    if (!rules_set) {
        PyErr_SetString(PyExc_RuntimeError, "grid: set_rules() first");
        return NULL;
    }
    if (w <= 2 * MARGIN || h <= 2 * MARGIN || (long long)w * h > 1LL << 30) {
        PyErr_SetString(PyExc_ValueError, "grid: size out of range");
        return NULL;
    }
    size_t cells = (size_t)w * h;
    Grid *g = calloc(1, sizeof *g);
    if (!g)
        return PyErr_NoMemory();
    g->xmin = xmin, g->ymin = ymin, g->w = w, g->h = h;
    g->occ = calloc(cells, 1);
    g->seen = calloc(cells, sizeof *g->seen);
    g->reach = calloc(cells, sizeof *g->reach);
    g->parent = malloc(cells * sizeof *g->parent);
    g->queue = malloc(cells * sizeof *g->queue);
    g->rule = malloc(cells);
    g->dist = malloc(cells * sizeof *g->dist);
    g->disc = malloc(cells * sizeof *g->disc);
    g->low = malloc(cells * sizeof *g->low);
    g->side = malloc(cells);
    g->cut = malloc(cells);
    if (!g->occ || !g->seen || !g->reach || !g->parent || !g->queue || !g->rule || !g->dist
        || !g->disc || !g->low || !g->side || !g->cut) {
        release(g);
        return PyErr_NoMemory();
    }
    for (int b = 0; b < RING; b++)
        g->ring_d[b] = ring_dy[b] * w + ring_dx[b];
    for (int b = 0; b < SIDES; b++)
        g->side_d[b] = side_dy[b] * w + side_dx[b];
    for (int r = 0; r < rule_count; r++) {
        g->sub_d[r] = rule_sy[r] * w + rule_sx[r];
        g->goal_d[r] = rule_gy[r] * w + rule_gx[r];
    }
    PyObject *capsule = PyCapsule_New(g, CAPSULE, grid_free);
    if (!capsule)
        release(g);
    return capsule;
}

/* put(grid, cell, occupied) */
static PyObject *put(PyObject *self, PyObject *args)
{
    PyObject *capsule, *cell;
    int value;
    if (!PyArg_ParseTuple(args, "OOp", &capsule, &cell, &value))
        return NULL;
    Grid *g = grid_of(capsule);
    if (!g)
        return NULL;
    int32_t i = cell_index(g, cell);
    if (i < 0)
        return NULL;
    g->occ[i] = (uint8_t)value;
    Py_RETURN_NONE;
}

/* Breadth-first rotations of the module at `start` (counted as absent) until
 * `target`; 1 when reached (parents in g->parent / g->rule). */
static int search_path(Grid *g, int32_t start, int32_t target)
{
    next_stamp(&g->stamp, g->seen, (size_t)g->w * g->h);
    uint32_t stamp = g->stamp;
    uint8_t saved = g->occ[start];
    g->occ[start] = 0;
    g->seen[start] = stamp;
    g->parent[start] = -1;
    int32_t head = 0, tail = 0;
    g->queue[tail++] = start;
    int found = 0;
    while (head < tail && !found) {
        int32_t cell = g->queue[head++];
        unsigned mask = ring_mask(g, cell);
        for (int r = 0; r < rule_count; r++) {
            if (!is_open(mask, r))
                continue;
            int32_t goal = cell + g->goal_d[r];
            if (g->seen[goal] == stamp)
                continue;
            g->seen[goal] = stamp;
            g->parent[goal] = cell;
            g->rule[goal] = (int8_t)r;
            if (goal == target) {
                found = 1;
                break;
            }
            g->queue[tail++] = goal;
        }
    }
    g->occ[start] = saved;
    return found;
}

/* The hops start -> target of the last search: [(src, dst, rotation, substrate)]. */
static PyObject *hops_to(const Grid *g, int32_t target)
{
    int32_t length = 0;
    for (int32_t c = target; g->parent[c] >= 0; c = g->parent[c])
        length++;
    PyObject *hops = PyList_New(length);
    if (!hops)
        return NULL;
    for (int32_t c = target, k = length - 1; k >= 0; c = g->parent[c], k--) {
        int32_t prev = g->parent[c];
        int r = g->rule[c];
        PyObject *src = cell_at(g, prev), *dst = cell_at(g, c);
        PyObject *sub = cell_at(g, prev + g->sub_d[r]);
        PyObject *hop = (src && dst && sub) ? Py_BuildValue("(OOiO)", src, dst, r, sub) : NULL;
        Py_XDECREF(src), Py_XDECREF(dst), Py_XDECREF(sub);
        if (!hop) {
            Py_DECREF(hops);
            return NULL;
        }
        PyList_SET_ITEM(hops, k, hop);
    }
    return hops;
}

/* path(grid, start, target) -> hops or None */
static PyObject *path(PyObject *self, PyObject *args)
{
    PyObject *capsule, *start_cell, *target_cell;
    if (!PyArg_ParseTuple(args, "OOO", &capsule, &start_cell, &target_cell))
        return NULL;
    Grid *g = grid_of(capsule);
    if (!g)
        return NULL;
    int32_t start = cell_index(g, start_cell), target = cell_index(g, target_cell);
    if (start < 0 || target < 0)
        return NULL;
    if (search_path(g, start, target))
        return hops_to(g, target);
    Py_RETURN_NONE;
}

/* Every cell from which a module rolls to `target`, all modules fixed (marks),
 * with its rotations to it (g->dist). */
static void search_reach(Grid *g, int32_t target)
{
    next_stamp(&g->reach_stamp, g->reach, (size_t)g->w * g->h);
    uint32_t stamp = g->reach_stamp;
    int32_t head = 0, tail = 0;
    g->reach[target] = stamp;
    g->dist[target] = 0;
    g->queue[tail++] = target;
    while (head < tail) {
        int32_t cell = g->queue[head++];
        unsigned mask = ring_mask(g, cell);
        for (int r = 0; r < rule_count; r++) {
            if (!is_open(mask, r))
                continue;
            int32_t goal = cell + g->goal_d[r];
            if (g->reach[goal] != stamp) {
                g->reach[goal] = stamp;
                g->dist[goal] = g->dist[cell] + 1;
                g->queue[tail++] = goal;
            }
        }
    }
}

static int enters_reach(const Grid *g, int32_t cell)
{
    unsigned mask = ring_mask(g, cell);
    for (int r = 0; r < rule_count; r++)
        if (is_open(mask, r) && g->reach[cell + g->goal_d[r]] == g->reach_stamp)
            return 1;
    return 0;
}

/* Its occupied neighbours in one arc: removing it disconnects nothing. */
static int single_arc(const Grid *g, int32_t cell)
{
    int ring[SIDES], all = 1, changes = 0;
    for (int s = 0; s < SIDES; s++) {
        ring[s] = g->occ[cell + g->side_d[s]];
        all &= ring[s];
    }
    if (all)
        return 1;
    for (int s = 0; s < SIDES; s++)
        changes += ring[s] && !ring[(s + SIDES - 1) % SIDES];
    return changes <= 1;
}

static PyObject *found(const Grid *g, Py_ssize_t k, int32_t target)
{
    PyObject *hops = hops_to(g, target);
    if (!hops)
        return NULL;
    PyObject *out = Py_BuildValue("(nO)", k, hops);
    Py_DECREF(hops);
    return out;
}

/* Cut vertices of the occupied cells (one depth-first pass, Hopcroft-Tarjan low
 * points, iterative) into g->cut; the occupied cells are one piece. */
static void find_cuts(Grid *g)
{
    size_t cells = (size_t)g->w * g->h;
    memset(g->cut, 0, cells);
    memset(g->disc, 0, cells * sizeof *g->disc);
    int32_t root = -1;
    for (size_t i = 0; i < cells && root < 0; i++)
        if (g->occ[i])
            root = (int32_t)i;
    if (root < 0)
        return;
    int32_t clock = 1, top = 0, root_children = 0;
    g->disc[root] = g->low[root] = clock++;
    g->parent[root] = -1;
    g->queue[top] = root, g->side[top] = 0, top++;
    while (top) {
        int32_t v = g->queue[top - 1];
        if (g->side[top - 1] < SIDES) {
            int32_t w = v + g->side_d[g->side[top - 1]++];
            if (!g->occ[w])
                continue;
            if (!g->disc[w]) {
                g->parent[w] = v;
                g->disc[w] = g->low[w] = clock++;
                g->queue[top] = w, g->side[top] = 0, top++;
                root_children += v == root;
            } else if (w != g->parent[v] && g->disc[w] < g->low[v]) {
                g->low[v] = g->disc[w];
            }
            continue;
        }
        top--;
        int32_t p = g->parent[v];
        if (p < 0)
            continue;
        if (g->low[v] < g->low[p])
            g->low[p] = g->low[v];
        if (p != root && g->low[v] >= g->disc[p])
            g->cut[p] = 1;
    }
    g->cut[root] = root_children > 1;
}

/* The grid, a list of cells checked to be a list, and the target's index
 * (NULL with an exception when one of them is wrong). */
static Grid *grid_list_target(PyObject *capsule, PyObject *list, PyObject *target_cell,
                              const char *what, int32_t *target)
{
    Grid *g = grid_of(capsule);
    if (!g)
        return NULL;
    if (!PyList_Check(list)) {
        PyErr_Format(PyExc_TypeError, "%s must be a list of cells", what);
        return NULL;
    }
    *target = cell_index(g, target_cell);
    return *target < 0 ? NULL : g;
}

/* pick(grid, order, target, farthest, tries) -> (k, hops) or None
 *
 * canonical.StripGrid.pick: the first `tries` modules of `order` get a path
 * search each; then one search outward from `target`, and the modules are
 * scanned in order for a first rotation into what it reached: those before
 * `farthest`, or with their neighbours in one arc, get a path search. Only
 * when none has a path, one cut-vertex pass, and the others that scan found
 * and are no cut vertex get one; last, every other module that is not. */
static PyObject *pick(PyObject *self, PyObject *args)
{
    PyObject *capsule, *order, *target_cell;
    Py_ssize_t farthest, tries;
    if (!PyArg_ParseTuple(args, "OOOnn", &capsule, &order, &target_cell, &farthest, &tries))
        return NULL;
    int32_t target;
    Grid *g = grid_list_target(capsule, order, target_cell, "pick: order", &target);
    if (!g)
        return NULL;
    Py_ssize_t count = PyList_GET_SIZE(order);
    int32_t *at = malloc((count + 1) * sizeof *at);  /* order's cells; -1: scanned */
    uint8_t *unsure = calloc(count + 1, 1);
    PyObject *out = NULL;
    if (!at || !unsure) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t k = 0; k < count; k++)
        if ((at[k] = cell_index(g, PyList_GET_ITEM(order, k))) < 0)
            goto done;
    for (Py_ssize_t k = 0; k < tries && k < count; k++)
        if (search_path(g, at[k], target)) {
            out = found(g, k, target);
            goto done;
        }
    search_reach(g, target);
    int any_unsure = 0;
    for (Py_ssize_t k = 0; k < count; k++) {
        int32_t cell = at[k];
        if (!enters_reach(g, cell))
            continue;
        at[k] = -1;  /* looked at: the last pass skips it */
        if (k < farthest || single_arc(g, cell)) {
            if (search_path(g, cell, target)) {
                out = found(g, k, target);
                goto done;
            }
        } else {
            unsure[k] = 1, any_unsure = 1;
            at[k] = -2 - cell;  /* keep the cell */
        }
    }
    find_cuts(g);
    if (any_unsure)
        for (Py_ssize_t k = 0; k < count; k++) {
            if (!unsure[k])
                continue;
            int32_t cell = -2 - at[k];
            if (!g->cut[cell] && search_path(g, cell, target)) {
                out = found(g, k, target);
                goto done;
            }
        }
    for (Py_ssize_t k = 0; k < count; k++) {
        int32_t cell = at[k];
        if (cell >= 0 && !g->cut[cell] && search_path(g, cell, target)) {
            out = found(g, k, target);
            goto done;
        }
    }
    out = Py_NewRef(Py_None);
done:
    free(at), free(unsure);
    return out;
}

/* nearest(grid, cells, target) -> [(rotations, k)]: for each module of `cells`
 * whose first rotation lands where a module rolls to `target` from, the fewest
 * rotations from such a landing cell (canonical._hop's ranking). */
static PyObject *nearest(PyObject *self, PyObject *args)
{
    PyObject *capsule, *cells, *target_cell;
    if (!PyArg_ParseTuple(args, "OOO", &capsule, &cells, &target_cell))
        return NULL;
    int32_t target;
    Grid *g = grid_list_target(capsule, cells, target_cell, "nearest: cells", &target);
    if (!g)
        return NULL;
    search_reach(g, target);
    PyObject *out = PyList_New(0);
    for (Py_ssize_t k = 0; out && k < PyList_GET_SIZE(cells); k++) {
        int32_t cell = cell_index(g, PyList_GET_ITEM(cells, k));
        if (cell < 0) {
            Py_CLEAR(out);
            break;
        }
        unsigned mask = ring_mask(g, cell);
        int32_t best = -1;
        for (int r = 0; r < rule_count; r++) {
            int32_t goal = cell + g->goal_d[r];
            if (is_open(mask, r) && g->reach[goal] == g->reach_stamp
                && (best < 0 || g->dist[goal] < best))
                best = g->dist[goal];
        }
        if (best < 0)
            continue;
        PyObject *item = Py_BuildValue("(in)", best, k);
        if (!item || PyList_Append(out, item) < 0)
            Py_CLEAR(out);
        Py_XDECREF(item);
    }
    return out;
}

/* Moves made without the frozen dataclass's __init__, which sets each field
 * through object.__setattr__ (2.5 us a move; a strip plan of 10,000 modules
 * makes 8 million). The fields are set through their slot descriptors, as
 * object.__setattr__ would. */
#define MOVE_FIELDS 7
static PyTypeObject *move_type;
static PyObject *move_slots[MOVE_FIELDS];

/* set_move_type(Move, field names in order) */
static PyObject *set_move_type(PyObject *self, PyObject *args)
{
    PyObject *type, *names;
    if (!PyArg_ParseTuple(args, "O!O", &PyType_Type, &type, &names))
        return NULL;
    PyObject *fast = PySequence_Fast(names, "names");
    if (!fast)
        return NULL;
    if (PySequence_Fast_GET_SIZE(fast) != MOVE_FIELDS) {
        Py_DECREF(fast);
        PyErr_SetString(PyExc_ValueError, "set_move_type: 7 field names expected");
        return NULL;
    }
    PyObject *slots[MOVE_FIELDS] = {0};
    for (int i = 0; i < MOVE_FIELDS; i++) {
        slots[i] = PyObject_GetAttr(type, PySequence_Fast_GET_ITEM(fast, i));
        if (!slots[i] || !Py_IS_TYPE(slots[i], &PyMemberDescr_Type)) {
            if (slots[i])
                PyErr_SetString(PyExc_TypeError, "set_move_type: fields must be slots");
            for (int j = 0; j <= i; j++)
                Py_XDECREF(slots[j]);
            Py_DECREF(fast);
            return NULL;
        }
    }
    Py_DECREF(fast);
    for (int i = 0; i < MOVE_FIELDS; i++)
        Py_XSETREF(move_slots[i], slots[i]);
    Py_XSETREF(move_type, (PyTypeObject *)Py_NewRef(type));
    Py_RETURN_NONE;
}

/* new_move(module, src, dst, joint, direction, substrate, substrate_module) -> Move */
static PyObject *new_move(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!move_type) {
        PyErr_SetString(PyExc_RuntimeError, "new_move: set_move_type() first");
        return NULL;
    }
    if (nargs != MOVE_FIELDS) {
        PyErr_SetString(PyExc_TypeError, "new_move: 7 arguments expected");
        return NULL;
    }
    PyObject *move = move_type->tp_alloc(move_type, 0);
    if (!move)
        return NULL;
    for (int i = 0; i < MOVE_FIELDS; i++)
        if (Py_TYPE(move_slots[i])->tp_descr_set(move_slots[i], move, args[i]) < 0) {
            Py_DECREF(move);
            return NULL;
        }
    return move;
}

static PyMethodDef methods[] = {
    {"set_move_type", set_move_type, METH_VARARGS, "set_move_type(Move, field names)"},
    {"new_move", (PyCFunction)(void (*)(void))new_move, METH_FASTCALL,
     "new_move(module, src, dst, joint, direction, substrate, substrate_module) -> Move,"
     " without the dataclass __init__"},
    {"nearest", nearest, METH_VARARGS,
     "nearest(grid, cells, target) -> [(rotations, k)] for the cells that can head for target"},
    {"set_rules", set_rules, METH_VARARGS, "set_rules(ring, rotations, sides)"},
    {"grid", grid_new, METH_VARARGS, "grid(xmin, ymin, width, height) -> an empty grid"},
    {"put", put, METH_VARARGS, "put(grid, cell, occupied)"},
    {"path", path, METH_VARARGS,
     "path(grid, start, target) -> [(src, dst, rotation index, substrate)] or None"},
    {"pick", pick, METH_VARARGS,
     "pick(grid, order, target, farthest, tries) -> (k, hops) or None"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_strip",
    "The canonical strip route's mover pick and path search over an occupancy grid.", -1,
    methods,
};

PyMODINIT_FUNC PyInit__strip(void)
{
    return PyModule_Create(&module);
}
