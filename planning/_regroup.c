/*
 * hexbot.planning._regroup: one pass of regroup (a few modules' moves in a
 * small area re-planned together), in C.
 *
 * The pass slides over the serial plan. At each stop it takes the longest
 * run of consecutive moves whose cells (start, goal, swept, substrate) stay
 * within `reach` of each other, at most `most` moves, and searches (A*)
 * the fewest rotations that take the same area from the configuration
 * before the run to the one after it, every module outside the area fixed.
 * Modules are interchangeable there: a search may send another module than
 * the plan did, which is where it finds what tidy's single-module rolls do
 * not (a module steps aside and another fills its cell: one roll instead).
 * When it finds fewer rotations than the run made, they replace the run;
 * both end in the same configuration, so nothing later changes.
 *
 * A search only moves a module whose occupied neighbours form one arc and
 * that has three free sides in a row (so it can leave and the rest stays
 * one piece, whatever lies outside the area); the module bolted to the
 * base never moves.
 *
 * No geometry lives here: regroup.py hands over, once, the 12 cells around
 * a mobile module, the Table 4-3 rotations (substrate bit, goal and swept
 * bits, substrate and goal offsets), the six sides and the table of rings
 * a module can leave; with each pass the lattice distance of every offset
 * of its grid.
 */
#include "_rules.h"
#include <stdlib.h>
#include <string.h>

#define AREA 128          /* cells of a search's area at most: two words a state */
#define MAX_DIFF 32       /* cells a state differs from the target in, for the bound */
#define DEADLINE_EVERY 8  /* stops between two looks at the deadline */
#define MAX_RUN 100       /* moves in a run at most */

#define leavable ring_table /* set_rules' table: can a module with that ring leave? */

typedef struct {
    uint64_t bits[2];
} State;

/* A state the search reached: how, in how many rotations. */
typedef struct {
    State state;
    int32_t parent;
    int16_t g;
    int8_t from, rot; /* the rotation that led here: area cell, rule */
} Node;

typedef struct {
    int32_t f, g, node;
} Open;

typedef struct {
    int w, h;
    size_t cells;
    uint8_t *grid;              /* 0 empty, 1 a module, 2 the bolted module */
    const int32_t *dist;        /* lattice distance by offset (see distance()) */
    int16_t *area_of;           /* grid cell -> its index in the area, or -1 */
    int ring_d[RING], side_d[SIDES], sub_d[MAX_RULES], goal_d[MAX_RULES];
    int32_t *plan;              /* two ints a move: start cell, rotation */
    Py_ssize_t n;
    /* the search */
    int32_t area[AREA];
    int area_len;
    Node *nodes;
    int32_t node_count, max_states;
    int32_t *table;             /* open addressing over nodes, -1 = free */
    uint32_t table_mask;
    Open *heap;
    int32_t heap_len, heap_cap;
    int32_t found[2 * MAX_RUN]; /* the rotations found: (cell, rule) pairs */
    /* search_area only: the component (of the modules outside the area) of each
     * grid cell, -1 for none; NULL: a module must have its neighbours in one arc */
    const int32_t *labels;
    int32_t label_count;
    /* improve_area only: the area's goal cells; the search stops at the first
     * state it reaches that is worse off than `before` by less (badness()) */
    int improve;
    State goal_cells;
    int before;
} Pass;

static void pass_free(Pass *p)
{
    free(p->grid), free(p->area_of), free(p->plan);
    free(p->nodes), free(p->table), free(p->heap);
}

/* set_rules(ring, rotations, sides, leavable): see _rules.h; leavable = 64
 * booleans (bit i of a mask: side i occupied): can a module with that ring
 * leave? */
static PyObject *set_rules(PyObject *self, PyObject *args)
{
    return read_rules(args, "leavable");
}

static inline int32_t distance(const Pass *p, int32_t a, int32_t b)
{
    return grid_distance(p->dist, p->w, p->h, a, b);
}

static inline unsigned ring_mask(const Pass *p, int32_t i)
{
    unsigned mask = 0;
    for (int b = 0; b < RING; b++)
        if (p->grid[i + p->ring_d[b]])
            mask |= 1u << b;
    return mask;
}

static inline int can_leave(const Pass *p, int32_t cell)
{
    unsigned mask = 0;
    for (int i = 0; i < SIDES; i++)
        if (p->grid[cell + p->side_d[i]])
            mask |= 1u << i;
    return leavable[mask];
}

static int32_t find_root(int32_t *parent, int32_t i)
{
    while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
    return i;
}

/* Can the module at `cell` leave without cutting the configuration? The ring
 * test first; with labels, a module whose neighbours form several arcs may
 * leave when they stay joined: through the area's other modules and the
 * outside components (a union-find over both, the area's state on the grid). */
static int can_move(const Pass *p, int32_t cell)
{
    if (can_leave(p, cell))
        return 1;
    if (!p->labels)
        return 0;
    unsigned sides = 0;
    for (int i = 0; i < SIDES; i++)
        if (p->grid[cell + p->side_d[i]])
            sides |= 1u << i;
    unsigned twice = sides | sides << SIDES; /* three free sides in a row, round the ring */
    int run = 0;
    for (int i = 0; i < SIDES + 2 && run < 3; i++)
        run = twice >> i & 1 ? 0 : run + 1;
    if (run < 3)
        return 0; /* no rotation at all: spare the union-find */
    int32_t parent[AREA + 4 * AREA];
    int32_t nodes = p->area_len + p->label_count;
    if (nodes > AREA + 4 * AREA)
        return 0;
    for (int32_t i = 0; i < nodes; i++)
        parent[i] = i;
    for (int i = 0; i < p->area_len; i++) {
        int32_t c = p->area[i];
        if (c == cell || !p->grid[c])
            continue;
        for (int s = 0; s < SIDES; s++) {
            int32_t n = c + p->side_d[s], other = -1;
            if (n == cell || !p->grid[n])
                continue;
            if (p->area_of[n] >= 0)
                other = p->area_of[n];
            else if (p->labels[n] >= 0)
                other = p->area_len + p->labels[n];
            if (other >= 0) {
                int32_t a = find_root(parent, i), b = find_root(parent, other);
                if (a != b)
                    parent[a] = b;
            }
        }
    }
    int32_t root = -1;
    for (int s = 0; s < SIDES; s++) {
        int32_t n = cell + p->side_d[s], node = -1;
        if (!p->grid[n])
            continue;
        if (p->area_of[n] >= 0)
            node = p->area_of[n];
        else if (p->labels[n] >= 0)
            node = p->area_len + p->labels[n];
        else
            return 0; /* a module the labels do not know: be safe */
        int32_t r = find_root(parent, node);
        if (root < 0)
            root = r;
        else if (r != root)
            return 0;
    }
    return 1;
}

/* The cells a move needs: start, substrate, goal and swept ones. */
static int move_cells(const Pass *p, int32_t src, int rot, int32_t *out)
{
    int k = 0;
    out[k++] = src;
    out[k++] = src + p->sub_d[rot];
    for (int b = 0; b < RING; b++)
        if (rule_free[rot] >> b & 1)
            out[k++] = src + p->ring_d[b];
    return k;
}

static inline void apply(Pass *p, int32_t src, int rot)
{
    p->grid[src + p->goal_d[rot]] = p->grid[src];
    p->grid[src] = 0;
}

static inline int has(const State *s, int i)
{
    return s->bits[i >> 6] >> (i & 63) & 1;
}

static inline void flip(State *s, int i)
{
    s->bits[i >> 6] ^= 1ull << (i & 63);
}

static inline int same(const State *a, const State *b)
{
    return a->bits[0] == b->bits[0] && a->bits[1] == b->bits[1];
}

static inline uint32_t hash(const State *s)
{
    uint64_t x = s->bits[0] * 0x9E3779B97F4A7C15ull ^ (s->bits[1] + 0x632BE59BD9B4E019ull)
        * 0xC2B2AE3D27D4EB4Full;
    return (uint32_t)(x ^ x >> 29);
}

/* The cheapest assignment of the area cells a state holds and the target
 * does not onto those the target holds and the state does not (Hungarian
 * method): no plan of the area does it in fewer rotations, and one rotation
 * changes it by at most one, so A* with it finds the fewest. */
static int32_t bound(const Pass *p, const State *s, const State *target)
{
    int off[MAX_DIFF + 1], empty[MAX_DIFF + 1], k = 0, e = 0;
    for (int i = 0; i < p->area_len; i++) {
        int a = has(s, i), b = has(target, i);
        if (a && !b) {
            if (k == MAX_DIFF)
                return 0; /* too many to assign: no bound, still correct */
            off[k++] = p->area[i];
        } else if (b && !a && e < MAX_DIFF) {
            empty[e++] = p->area[i];
        }
    }
    if (k == 0 || k != e)
        return 0;
    /* e-maxx Hungarian, 1-based, over the k x k distances */
    int32_t u[MAX_DIFF + 1] = {0}, v[MAX_DIFF + 1] = {0}, way[MAX_DIFF + 1];
    int match[MAX_DIFF + 1] = {0};
    for (int i = 1; i <= k; i++) {
        int32_t minv[MAX_DIFF + 1];
        uint8_t used[MAX_DIFF + 1] = {0};
        for (int j = 0; j <= k; j++)
            minv[j] = INT32_MAX;
        match[0] = i;
        int j0 = 0;
        do {
            used[j0] = 1;
            int i0 = match[j0], j1 = 0;
            int32_t delta = INT32_MAX;
            for (int j = 1; j <= k; j++) {
                if (used[j])
                    continue;
                int32_t cur = distance(p, off[i0 - 1], empty[j - 1]) - u[i0] - v[j];
                if (cur < minv[j])
                    minv[j] = cur, way[j] = j0;
                if (minv[j] < delta)
                    delta = minv[j], j1 = j;
            }
            for (int j = 0; j <= k; j++) {
                if (used[j])
                    u[match[j]] += delta, v[j] -= delta;
                else
                    minv[j] -= delta;
            }
            j0 = j1;
        } while (match[j0] != 0);
        do {
            int j1 = way[j0];
            match[j0] = match[j1];
            j0 = j1;
        } while (j0);
    }
    return -v[0];
}

/* improve_area's measure of a state: its modules off the goal plus its goal
 * cells left empty (what windows.py calls badness). */
static int badness(const Pass *p, const State *s)
{
    int count = 0;
    for (int w = 0; w < 2; w++)
        count += __builtin_popcountll(s->bits[w] & ~p->goal_cells.bits[w])
            + __builtin_popcountll(p->goal_cells.bits[w] & ~s->bits[w]);
    return count;
}

/* improve_area's estimate: one rotation moves one module one cell, so a
 * module off the goal needs the distance to the nearest empty goal cell,
 * less one (the rotation that lowers the badness may end next to it). */
static int32_t estimate(const Pass *p, const State *s)
{
    int32_t best = INT32_MAX;
    for (int i = 0; i < p->area_len; i++) {
        if (!has(s, i) || has(&p->goal_cells, i))
            continue;
        for (int j = 0; j < p->area_len; j++)
            if (has(&p->goal_cells, j) && !has(s, j)) {
                int32_t d = distance(p, p->area[i], p->area[j]);
                if (d < best)
                    best = d;
            }
    }
    return best == INT32_MAX || best < 1 ? 0 : best - 1;
}

/* The heuristic of the search's mode, a lower bound on the rotations still
 * needed. */
static inline int32_t heuristic(const Pass *p, const State *s, const State *target)
{
    return p->improve ? estimate(p, s) : bound(p, s, target);
}

static void heap_push(Pass *p, Open item)
{
    int32_t i = p->heap_len++;
    while (i > 0) {
        int32_t up = (i - 1) / 2;
        Open *q = &p->heap[up];
        if (q->f < item.f || (q->f == item.f && q->g >= item.g))
            break;
        p->heap[i] = *q;
        i = up;
    }
    p->heap[i] = item;
}

static Open heap_pop(Pass *p)
{
    Open top = p->heap[0], last = p->heap[--p->heap_len];
    int32_t i = 0;
    for (;;) {
        int32_t c = 2 * i + 1;
        if (c >= p->heap_len)
            break;
        if (c + 1 < p->heap_len && (p->heap[c + 1].f < p->heap[c].f
                                    || (p->heap[c + 1].f == p->heap[c].f
                                        && p->heap[c + 1].g > p->heap[c].g)))
            c++;
        if (last.f < p->heap[c].f || (last.f == p->heap[c].f && last.g >= p->heap[c].g))
            break;
        p->heap[i] = p->heap[c];
        i = c;
    }
    p->heap[i] = last;
    return top;
}

/* The node of `s`, added (with g = INT16_MAX) if new; -1 when full. */
static int32_t lookup(Pass *p, const State *s)
{
    uint32_t slot = hash(s) & p->table_mask;
    for (;;) {
        int32_t k = p->table[slot];
        if (k < 0)
            break;
        if (same(&p->nodes[k].state, s))
            return k;
        slot = (slot + 1) & p->table_mask;
    }
    if (p->node_count == p->max_states)
        return -1;
    int32_t k = p->node_count++;
    p->nodes[k] = (Node){*s, -1, INT16_MAX, -1, -1};
    p->table[slot] = k;
    return k;
}

/* Write a state's cells into the grid (the bolted module keeps its mark). */
static void write_state(Pass *p, const State *s)
{
    for (int i = 0; i < p->area_len; i++) {
        uint8_t *c = &p->grid[p->area[i]];
        if (*c != 2)
            *c = (uint8_t)has(s, i);
    }
}

/* The fewest rotations (fewer than `limit`) from `start` to `target` inside
 * the area, into p->found; their number, or -1. The grid is left as it was.
 * In improve mode (target unused) it stops at the first state it reaches
 * whose badness is below p->before: tested when a state is reached, not
 * when it is taken from the heap, so that is at most one rotation more
 * than the fewest (the popped state's f is at most the fewest's). */
static int search(Pass *p, const State *start, const State *target, int limit)
{
    memset(p->table, 0xff, (size_t)(p->table_mask + 1) * sizeof *p->table);
    p->node_count = 0, p->heap_len = 0;
    int32_t first = lookup(p, start);
    p->nodes[first].g = 0;
    heap_push(p, (Open){heuristic(p, start, target), 0, first});
    int32_t goal = -1;
    while (p->heap_len) {
        Open top = heap_pop(p);
        Node *node = &p->nodes[top.node];
        if (top.g != node->g)
            continue; /* reached again since, by fewer rotations */
        if (!p->improve && same(&node->state, target)) {
            goal = top.node;
            break;
        }
        if (top.f >= limit)
            break; /* everything left needs `limit` rotations or more */
        State here = node->state;
        write_state(p, &here);
        int full = 0;
        for (int i = 0; i < p->area_len && !full && goal < 0; i++) {
            int32_t cell = p->area[i];
            if (p->grid[cell] != 1 || !can_move(p, cell))
                continue;
            unsigned mask = ring_mask(p, cell);
            for (int r = 0; r < rule_count; r++) {
                if (!is_open(mask, r))
                    continue;
                int to = p->area_of[cell + p->goal_d[r]];
                if (to < 0)
                    continue; /* the area's edge */
                State next = here;
                flip(&next, i), flip(&next, to);
                int32_t k = lookup(p, &next);
                if (k < 0) {
                    full = 1;
                    break;
                }
                Node *n = &p->nodes[k];
                if (n->g <= top.g + 1)
                    continue;
                n->g = (int16_t)(top.g + 1), n->parent = top.node;
                n->from = (int8_t)i, n->rot = (int8_t)r;
                if (p->improve && badness(p, &next) < p->before) {
                    goal = k; /* tested when reached, not when taken */
                    break;
                }
                int32_t f = top.g + 1 + heuristic(p, &next, target);
                if (f >= limit)
                    continue;
                if (p->heap_len == p->heap_cap) {
                    full = 1;
                    break;
                }
                heap_push(p, (Open){f, top.g + 1, k});
            }
        }
        if (full || goal >= 0)
            break;
    }
    if (goal < 0)
        return -1;
    int length = p->nodes[goal].g;
    for (int32_t k = goal, at = length - 1; at >= 0; k = p->nodes[k].parent, at--) {
        p->found[2 * at] = p->area[p->nodes[k].from];
        p->found[2 * at + 1] = p->nodes[k].rot;
    }
    return length;
}

static void forget_area(Pass *p);

/* The run of moves from `start` whose cells stay within `reach` of each
 * other, at most `most`: its last move. Its cells go to p->area (the area
 * is the run's cells and their neighbours, `pad` times). */
static Py_ssize_t take_run(Pass *p, Py_ssize_t start, int reach, int most, int pad)
{
    int32_t touched[AREA], cells[2 + RING];
    int count = 0;
    Py_ssize_t last = start - 1;
    for (Py_ssize_t k = start; k < p->n && k - start < most; k++) {
        int m = move_cells(p, p->plan[2 * k], p->plan[2 * k + 1], cells), fresh = 0;
        int32_t add[2 + RING];
        int ok = 1;
        for (int i = 0; i < m && ok; i++) {
            int seen = 0;
            for (int j = 0; j < count && !seen; j++)
                seen = touched[j] == cells[i];
            for (int j = 0; j < fresh && !seen; j++)
                seen = add[j] == cells[i];
            if (seen)
                continue;
            for (int j = 0; j < count && ok; j++)
                ok = distance(p, touched[j], cells[i]) <= reach;
            for (int j = 0; j < fresh && ok; j++)
                ok = distance(p, add[j], cells[i]) <= reach;
            add[fresh++] = cells[i];
        }
        if (!ok || count + fresh > AREA)
            break;
        memcpy(touched + count, add, (size_t)fresh * sizeof *add);
        count += fresh;
        last = k;
    }
    /* the area: the touched cells grown by `pad` rings of neighbours */
    p->area_len = 0;
    for (int i = 0; i < count; i++) {
        p->area_of[touched[i]] = (int16_t)p->area_len;
        p->area[p->area_len++] = touched[i];
    }
    for (int grow = 0, from = 0; grow < pad; grow++) {
        int to = p->area_len;
        for (int i = from; i < to; i++)
            for (int s = 0; s < SIDES; s++) {
                int32_t c = p->area[i] + p->side_d[s];
                if (p->area_of[c] >= 0)
                    continue;
                if (p->area_len == AREA) { /* too big: no search */
                    forget_area(p);
                    return last;
                }
                p->area_of[c] = (int16_t)p->area_len;
                p->area[p->area_len++] = c;
            }
        from = to;
    }
    return last;
}

static void forget_area(Pass *p)
{
    for (int i = 0; i < p->area_len; i++)
        p->area_of[p->area[i]] = -1;
    p->area_len = 0;
}

static int read_ints(PyObject *obj, Py_buffer *view, Py_ssize_t count, const char *what)
{
    if (PyObject_GetBuffer(obj, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    if (view->itemsize != 4 || !view->format || strcmp(view->format, "i") != 0
        || (count >= 0 && view->len != count * 4)) {
        PyErr_Format(PyExc_ValueError, "one_pass: %s must be C ints (%zd)", what, count);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

/* The occupancy grid: width * height bytes (0 empty, 1 module, 2 bolted). */
static int read_grid(PyObject *obj, Py_buffer *view, int w, int h, const char *who)
{
    if (PyObject_GetBuffer(obj, view, PyBUF_C_CONTIGUOUS) < 0)
        return -1;
    if (view->len != (Py_ssize_t)w * h) {
        PyErr_Format(PyExc_ValueError, "%s: grid must be width * height bytes", who);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

static State area_state(const Pass *p)
{
    State s = {{0, 0}};
    for (int i = 0; i < p->area_len; i++)
        if (p->grid[p->area[i]])
            flip(&s, i);
    return s;
}

/* Try the run from `start`: the plan shrinks when a search finds fewer
 * rotations. Returns the rotations saved. */
static Py_ssize_t regroup_run(Pass *p, Py_ssize_t start, int reach, int most, int pad)
{
    Py_ssize_t last = take_run(p, start, reach, most, pad), saved = 0;
    Py_ssize_t length = last - start + 1;
    if (length >= 3 && p->area_len > 0) {
        State before = area_state(p);
        for (Py_ssize_t k = start; k <= last; k++)
            apply(p, p->plan[2 * k], p->plan[2 * k + 1]);
        State after = area_state(p);
        write_state(p, &before);
        int found = search(p, &before, &after, (int)length);
        write_state(p, &before);
        if (found >= 0) {
            memcpy(p->plan + 2 * start, p->found, (size_t)found * 2 * sizeof *p->plan);
            memmove(p->plan + 2 * (start + found), p->plan + 2 * (last + 1),
                    (size_t)(p->n - last - 1) * 2 * sizeof *p->plan);
            p->n -= length - found;
            saved = length - found;
        }
    }
    forget_area(p);
    return saved;
}

/* (start, rotation) pairs as a list of tuples. */
static PyObject *pair_list(const int32_t *pairs, Py_ssize_t n)
{
    PyObject *result = PyList_New(n);
    if (!result)
        return NULL;
    for (Py_ssize_t k = 0; k < n; k++) {
        PyObject *item = Py_BuildValue("(ii)", pairs[2 * k], pairs[2 * k + 1]);
        if (!item) {
            Py_DECREF(result);
            return NULL;
        }
        PyList_SET_ITEM(result, k, item);
    }
    return result;
}

/* The search's tables for `max_states` states, the grid copied from `grid`,
 * no area yet, the rules' offsets for this grid's width. -1 (MemoryError
 * set) when out of memory; pass_free frees what was taken either way. */
static int pass_setup(Pass *p, const void *grid)
{
    uint32_t table_size = 1;
    while (table_size < 2u * (uint32_t)p->max_states)
        table_size <<= 1;
    p->table_mask = table_size - 1;
    p->grid = malloc(p->cells);
    p->area_of = malloc(p->cells * sizeof *p->area_of);
    p->nodes = malloc((size_t)p->max_states * sizeof *p->nodes);
    p->table = malloc((size_t)table_size * sizeof *p->table);
    /* a push per improvement of a node: four a node, and a search that
     * would push more stops as when it runs out of states */
    p->heap_cap = 4 * p->max_states;
    p->heap = malloc((size_t)p->heap_cap * sizeof *p->heap);
    if (!p->grid || !p->area_of || !p->nodes || !p->table || !p->heap) {
        PyErr_NoMemory();
        return -1;
    }
    memcpy(p->grid, grid, p->cells);
    memset(p->area_of, 0xff, p->cells * sizeof *p->area_of);
    for (int i = 0; i < RING; i++)
        p->ring_d[i] = ring_dx[i] + ring_dy[i] * p->w;
    for (int i = 0; i < SIDES; i++)
        p->side_d[i] = side_dx[i] + side_dy[i] * p->w;
    for (int r = 0; r < rule_count; r++)
        p->sub_d[r] = rule_sx[r] + rule_sy[r] * p->w, p->goal_d[r] = rule_gx[r] + rule_gy[r] * p->w;
    return 0;
}

/* one_pass(width, height, grid, plan, distances, reach, most, pad, stride,
 *          max_states, deadline) -> list of (start, rotation)
 *
 * grid: width * height bytes, 0 empty, 1 a module, 2 the module bolted to
 * the base, cell (x, y) at x + y * width; plan: 2 ints a move (start cell,
 * rotation); distances: (2 width - 1) * (2 height - 1) ints, the lattice
 * distance of the offset (dx, dy) at (dx + width - 1) + (dy + height - 1) *
 * (2 width - 1); reach, most, pad, stride, max_states: regroup.py's REACH,
 * MOST, PAD, STRIDE, STATES; deadline: its expired() is asked every 8
 * stops, and the pass ends there when it says so. Starts of the plan must
 * lie 4 + pad cells inside the grid. */
static PyObject *one_pass(PyObject *self, PyObject *args)
{
    int w, h, reach, most, pad, stride, max_states;
    PyObject *grid_obj, *plan_obj, *dist_obj, *deadline;
    if (!PyArg_ParseTuple(args, "iiOOOiiiiiO", &w, &h, &grid_obj, &plan_obj, &dist_obj,
                          &reach, &most, &pad, &stride, &max_states, &deadline))
        return NULL;
    if (!rules_set) {
        PyErr_SetString(PyExc_RuntimeError, "one_pass: set_rules first");
        return NULL;
    }
    if (w < 9 || h < 9 || (size_t)w * h > 1u << 28 || reach < 1 || most < 1 || most > MAX_RUN
        || pad < 0 || pad > 3 || stride < 1 || max_states < 1 || max_states > 1 << 24) {
        PyErr_SetString(PyExc_ValueError, "one_pass: a grid of at least 9 x 9, reach >= 1, "
                        "1-100 moves a run, pad 0-3, stride >= 1, 1 to 2**24 states");
        return NULL;
    }
    Py_buffer grid_view, plan_view, dist_view;
    if (read_grid(grid_obj, &grid_view, w, h, "one_pass") < 0)
        return NULL;
    if (read_ints(plan_obj, &plan_view, -1, "plan") < 0) {
        PyBuffer_Release(&grid_view);
        return NULL;
    }
    if (read_ints(dist_obj, &dist_view, (Py_ssize_t)(2 * w - 1) * (2 * h - 1),
                  "distances") < 0) {
        PyBuffer_Release(&grid_view), PyBuffer_Release(&plan_view);
        return NULL;
    }
    Py_ssize_t n = plan_view.len / 8;
    Pass p = {.w = w, .h = h, .cells = (size_t)w * h, .dist = dist_view.buf, .n = n,
              .max_states = max_states};
    PyObject *result = NULL;
    p.plan = malloc((size_t)(2 * n + 2) * sizeof *p.plan);
    if (!p.plan) {
        PyErr_NoMemory();
        goto done;
    }
    if (pass_setup(&p, grid_view.buf) < 0)
        goto done;
    memcpy(p.plan, plan_view.buf, (size_t)(2 * n) * sizeof *p.plan);
    int margin = 4 + pad;
    for (Py_ssize_t k = 0; k < n; k++) {
        int32_t src = p.plan[2 * k], rot = p.plan[2 * k + 1];
        int32_t x = src % w, y = src / w;
        if (rot < 0 || rot >= rule_count || src < 0 || (size_t)src >= p.cells
            || x < margin || x >= w - margin || y < margin || y >= h - margin) {
            PyErr_Format(PyExc_ValueError, "one_pass: move %zd is off the grid or "
                         "names no rotation", k);
            goto done;
        }
    }
    Py_ssize_t stops = 0;
    for (Py_ssize_t i = 0; i < p.n; stops++) {
        if (stops % DEADLINE_EVERY == 0) {
            PyObject *expired = PyObject_CallMethod(deadline, "expired", NULL);
            int stop = expired ? PyObject_IsTrue(expired) : -1;
            Py_XDECREF(expired);
            if (stop < 0)
                goto done;
            if (stop)
                break;
        }
        regroup_run(&p, i, reach, most, pad);
        for (Py_ssize_t k = i; k < i + stride && k < p.n; k++)
            apply(&p, p.plan[2 * k], p.plan[2 * k + 1]);
        i += stride;
    }
    result = pair_list(p.plan, p.n);
done:
    pass_free(&p);
    PyBuffer_Release(&grid_view), PyBuffer_Release(&plan_view), PyBuffer_Release(&dist_view);
    return result;
}

/* search_area(width, height, grid, distances, area, target, labels, label_count,
 *             max_states, limit) -> list of (start, rotation), or None
 *
 * One search on its own (planning/finish.py): the fewest rotations, fewer
 * than `limit` (at most 100), that take the cells `area` (grid cells, at
 * most 128, each 4 cells inside the grid) from the grid's occupancy to the
 * one where exactly the cells `target` are occupied, every module outside
 * the area fixed, modules interchangeable. None when there is none within
 * `max_states` states. grid and distances as for one_pass; labels: width *
 * height ints, the component of the modules outside the area that each grid
 * cell's module belongs to (-1: none), label_count of them, so that a module
 * whose neighbours form several arcs may move when they stay joined; None:
 * only a module whose neighbours form one arc moves.
 *
 * improve_area(...) takes the same arguments, `target` being the area's
 * goal cells, and finds rotations (fewer than `limit`; the fewest, or one
 * more: see search()) after which fewer area cells are wrong: a module off
 * the goal, or a goal cell empty (planning/windows.py's window fixes). */
static PyObject *area_search(PyObject *args, int improve)
{
    const char *who = improve ? "improve_area" : "search_area";
    int w, h, max_states, limit, label_count;
    PyObject *grid_obj, *dist_obj, *area_obj, *target_obj, *labels_obj;
    if (!PyArg_ParseTuple(args, "iiOOOOOiii", &w, &h, &grid_obj, &dist_obj, &area_obj,
                          &target_obj, &labels_obj, &label_count, &max_states, &limit))
        return NULL;
    if (!rules_set) {
        PyErr_Format(PyExc_RuntimeError, "%s: set_rules first", who);
        return NULL;
    }
    if (w < 9 || h < 9 || (size_t)w * h > 1u << 28 || max_states < 1 || max_states > 1 << 24
        || limit < 1 || limit > MAX_RUN) {
        PyErr_Format(PyExc_ValueError, "%s: a grid of at least 9 x 9, "
                     "1 to 2**24 states, a limit of 1-100 rotations", who);
        return NULL;
    }
    Py_buffer grid_view, dist_view, area_view, target_view, labels_view = {0};
    int have_grid = 0, have_dist = 0, have_area = 0, have_target = 0, have_labels = 0;
    PyObject *result = NULL;
    Pass p = {.w = w, .h = h, .cells = (size_t)w * h, .max_states = max_states,
              .improve = improve};
    if (read_grid(grid_obj, &grid_view, w, h, who) < 0)
        goto done;
    have_grid = 1;
    if (read_ints(dist_obj, &dist_view, (Py_ssize_t)(2 * w - 1) * (2 * h - 1),
                  "distances") < 0)
        goto done;
    have_dist = 1;
    if (read_ints(area_obj, &area_view, -1, "area") < 0)
        goto done;
    have_area = 1;
    if (read_ints(target_obj, &target_view, -1, "target") < 0)
        goto done;
    have_target = 1;
    if (labels_obj != Py_None) {
        if (read_ints(labels_obj, &labels_view, (Py_ssize_t)w * h, "labels") < 0)
            goto done;
        have_labels = 1;
        p.labels = labels_view.buf;
        p.label_count = label_count < 0 ? 0 : label_count;
    }
    p.dist = dist_view.buf;
    if (pass_setup(&p, grid_view.buf) < 0)
        goto done;
    const int32_t *area = area_view.buf, *target = target_view.buf;
    Py_ssize_t area_n = area_view.len / 4, target_n = target_view.len / 4;
    if (area_n < 1 || area_n > AREA) {
        PyErr_Format(PyExc_ValueError, "%s: 1 to 128 area cells", who);
        goto done;
    }
    for (Py_ssize_t i = 0; i < area_n; i++) {
        int32_t c = area[i], x = c % w, y = c / w;
        if (c < 0 || (size_t)c >= p.cells || x < 4 || x >= w - 4 || y < 4 || y >= h - 4
            || p.area_of[c] >= 0) {
            PyErr_Format(PyExc_ValueError, "%s: area cell %zd is off the grid's "
                         "inside or twice", who, i);
            goto done;
        }
        p.area_of[c] = (int16_t)i;
        p.area[p.area_len++] = c;
    }
    State goal = {{0, 0}};
    for (Py_ssize_t i = 0; i < target_n; i++) {
        int32_t c = target[i];
        if (c < 0 || (size_t)c >= p.cells || p.area_of[c] < 0) {
            PyErr_Format(PyExc_ValueError, "%s: target cell %zd is not in the area", who, i);
            goto done;
        }
        if (!has(&goal, p.area_of[c]))
            flip(&goal, p.area_of[c]);
    }
    State start = area_state(&p);
    if (improve) {
        p.goal_cells = goal;
        p.before = badness(&p, &start);
    }
    int found = search(&p, &start, &goal, limit);
    if (found < 0) {
        result = Py_NewRef(Py_None);
        goto done;
    }
    result = pair_list(p.found, found);
done:
    pass_free(&p);
    if (have_grid)
        PyBuffer_Release(&grid_view);
    if (have_dist)
        PyBuffer_Release(&dist_view);
    if (have_area)
        PyBuffer_Release(&area_view);
    if (have_target)
        PyBuffer_Release(&target_view);
    if (have_labels)
        PyBuffer_Release(&labels_view);
    return result;
}

static PyObject *search_area(PyObject *self, PyObject *args)
{
    return area_search(args, 0);
}

static PyObject *improve_area(PyObject *self, PyObject *args)
{
    return area_search(args, 1);
}

static PyMethodDef methods[] = {
    {"set_rules", set_rules, METH_VARARGS, "set_rules(ring, rotations, sides, leavable)"},
    {"one_pass", one_pass, METH_VARARGS,
     "one_pass(width, height, grid, plan, distances, reach, most, pad, stride, max_states, "
     "deadline) -> plan"},
    {"search_area", search_area, METH_VARARGS,
     "search_area(width, height, grid, distances, area, target, labels, label_count, "
     "max_states, limit) "
     "-> plan or None"},
    {"improve_area", improve_area, METH_VARARGS,
     "improve_area(width, height, grid, distances, area, goal_cells, labels, label_count, "
     "max_states, limit) -> plan or None"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "hexbot.planning._regroup",
    "One pass of regroup (moves in a small area re-planned together) over a grid.", -1,
    methods,
};

PyMODINIT_FUNC PyInit__regroup(void)
{
    PyObject *m = PyModule_Create(&module);
    if (m && PyModule_AddIntConstant(m, "AREA", AREA) < 0) /* cells of an area at most */
        Py_CLEAR(m);
    return m;
}
