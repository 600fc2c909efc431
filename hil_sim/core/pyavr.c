/*
 * pyavr.c -- Python binding: hexbot.hil_sim._avr.Cluster.
 *
 * A thin layer over cluster.c: argument checks, conversions, errors.
 *
 * run() releases the GIL while the MCUs run (on one thread or the cluster's
 * worker pool): nothing in cluster_run() calls back into Python.  Other
 * Python threads may then run, but not on this cluster: every method (and
 * attribute) refuses with RuntimeError while a run() of it is under way, so
 * the C state is only ever touched by the run or, between runs, under the
 * GIL.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "cluster.h"
#include "ir_medium.h"
#include "rf12_part.h"
#include "sim_core_config.h"

typedef struct {
	PyObject_HEAD
	cluster_t *c;
	int running; /* a run() with the GIL released is under way (read and set under the GIL) */
} ClusterObject;

/* 0, or -1 with RuntimeError set if a run() of this cluster is under way in
 * another thread. */
static int idle_or_fail(ClusterObject *self)
{
	if (!self->running)
		return 0;
	PyErr_SetString(PyExc_RuntimeError,
			"the cluster is running in another thread: wait for run() to return");
	return -1;
}

/* hexbot.protocol.timing.BAUD_TOLERANCE, read once at import: the one place
 * that number lives. */
static double baud_tolerance;

/* More threads than this is a typo, not a machine. */
#define MAX_THREADS 256

static m162_t *get_mcu(ClusterObject *self, long i)
{
	if (idle_or_fail(self) < 0)
		return NULL;
	if (i < 0 || i >= self->c->n) {
		PyErr_Format(PyExc_IndexError, "no MCU %ld (cluster has %d)", i, self->c->n);
		return NULL;
	}
	return self->c->mcu[i];
}

static m162_usart_t *get_usart(ClusterObject *self, long i, long u)
{
	m162_t *m = get_mcu(self, i);
	if (!m)
		return NULL;
	if (u < 0 || u >= M162_NUARTS) {
		PyErr_Format(PyExc_ValueError, "USART %ld does not exist (0 or 1)", u);
		return NULL;
	}
	return &m->usart[u];
}

static int port_index(const char *name)
{
	if (name && name[0] >= 'A' && name[0] <= 'E' && name[1] == 0)
		return name[0] - 'A';
	PyErr_Format(PyExc_ValueError, "port '%s' does not exist (A..E)", name ? name : "");
	return -1;
}

static m162_t *get_m162(ClusterObject *self, long i)
{
	m162_t *m = get_mcu(self, i);
	if (m && !m->is_m162) {
		PyErr_Format(PyExc_ValueError, "MCU %ld runs a stock simavr core (%s): no such access",
				i, m->avr->mmcu);
		return NULL;
	}
	return m;
}

/* The argument list "(mcu)" of most methods: the MCU, or NULL with the
 * Python error set. */
static m162_t *mcu_arg(ClusterObject *self, PyObject *args)
{
	long m;
	if (!PyArg_ParseTuple(args, "l", &m))
		return NULL;
	return get_mcu(self, m);
}

/* The same for methods that need our ATmega162 core. */
static m162_t *m162_arg(ClusterObject *self, PyObject *args)
{
	long m;
	if (!PyArg_ParseTuple(args, "l", &m))
		return NULL;
	return get_m162(self, m);
}

/* ---------------------------------------------------------------- */

static int set_threads(ClusterObject *self, long threads)
{
	if (threads < 1 || threads > MAX_THREADS) {
		PyErr_Format(PyExc_ValueError, "threads must be 1..%d, not %ld", MAX_THREADS, threads);
		return -1;
	}
	if (cluster_set_threads(self->c, (int)threads) < 0) {
		PyErr_Format(PyExc_OSError, "cannot start %ld simulation threads", threads);
		return -1;
	}
	return 0;
}

static int Cluster_init(ClusterObject *self, PyObject *args, PyObject *kw)
{
	static char *kwlist[] = { "quantum_cycles", "threads", NULL };
	long long q = 1000;
	long threads = 1;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "|Ll", kwlist, &q, &threads))
		return -1;
	if (idle_or_fail(self) < 0)
		return -1;
	if (q < 1) {
		PyErr_SetString(PyExc_ValueError, "quantum_cycles must be >= 1");
		return -1;
	}
	if (self->c)
		cluster_free(self->c);
	self->c = cluster_new((uint64_t)q, baud_tolerance);
	if (!self->c) {
		PyErr_NoMemory();
		return -1;
	}
	return set_threads(self, threads);
}

static void Cluster_dealloc(ClusterObject *self)
{
	cluster_free(self->c);
	Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyObject *Cluster_add_mcu(ClusterObject *self, PyObject *args, PyObject *kw)
{
	static char *kwlist[] = { "elf_path", "name", "core", NULL };
	PyObject *path_obj;
	const char *name, *core = "atmega162";
	if (idle_or_fail(self) < 0)
		return NULL;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "O&s|s", kwlist, PyUnicode_FSConverter,
			&path_obj, &name, &core))
		return NULL;
	const char *path = PyBytes_AS_STRING(path_obj);
	char err[512] = "";
	FILE *f = fopen(path, "rb");
	if (!f) {
		PyErr_Format(PyExc_FileNotFoundError, "%s: no such firmware file", path);
		Py_DECREF(path_obj);
		return NULL;
	}
	fclose(f);
	int idx = cluster_add(self->c, path, name, core, err, sizeof err);
	Py_DECREF(path_obj);
	if (idx < 0) {
		PyErr_SetString(PyExc_ValueError, err);
		return NULL;
	}
	return PyLong_FromLong(idx);
}

static PyObject *Cluster_get_cycle(ClusterObject *self, void *closure)
{
	(void)closure;
	if (idle_or_fail(self) < 0)
		return NULL;
	return PyLong_FromUnsignedLongLong(self->c->cycle);
}

static PyObject *Cluster_get_quantum(ClusterObject *self, void *closure)
{
	(void)closure;
	if (idle_or_fail(self) < 0)
		return NULL;
	return PyLong_FromUnsignedLongLong(self->c->quantum);
}

static PyObject *Cluster_get_frequency(ClusterObject *self, void *closure)
{
	(void)closure;
	if (idle_or_fail(self) < 0)
		return NULL;
	return PyLong_FromUnsignedLong(self->c->frequency ? self->c->frequency : 1000000);
}

static PyObject *Cluster_get_tolerance(ClusterObject *self, void *closure)
{
	(void)closure;
	if (idle_or_fail(self) < 0)
		return NULL;
	return PyFloat_FromDouble(self->c->baud_tolerance);
}

static PyObject *Cluster_get_threads(ClusterObject *self, void *closure)
{
	(void)closure;
	if (idle_or_fail(self) < 0)
		return NULL;
	return PyLong_FromLong(self->c->threads);
}

/* A whole-number attribute being set while no run is under way: 0 and *out,
 * or -1 with the Python error set. */
static int long_to_set(ClusterObject *self, PyObject *value, const char *name, long *out)
{
	if (!value) {
		PyErr_Format(PyExc_AttributeError, "%s cannot be deleted", name);
		return -1;
	}
	*out = PyLong_AsLong(value);
	if (*out == -1 && PyErr_Occurred())
		return -1;
	return idle_or_fail(self);
}

static int Cluster_set_threads(ClusterObject *self, PyObject *value, void *closure)
{
	(void)closure;
	long threads;
	if (long_to_set(self, value, "threads", &threads) < 0)
		return -1;
	return set_threads(self, threads);
}

static PyObject *Cluster_get_min_per_thread(ClusterObject *self, void *closure)
{
	(void)closure;
	if (idle_or_fail(self) < 0)
		return NULL;
	return PyLong_FromLong(self->c->min_per_thread);
}

static int Cluster_set_min_per_thread(ClusterObject *self, PyObject *value, void *closure)
{
	(void)closure;
	long v;
	if (long_to_set(self, value, "min_mcus_per_thread", &v) < 0)
		return -1;
	if (v < 1 || v > 1000000) {
		PyErr_Format(PyExc_ValueError, "min_mcus_per_thread must be >= 1, not %ld", v);
		return -1;
	}
	self->c->min_per_thread = (int)v;
	return 0;
}

static PyObject *Cluster_get_count(ClusterObject *self, void *closure)
{
	(void)closure;
	if (idle_or_fail(self) < 0)
		return NULL;
	return PyLong_FromLong(self->c->n);
}

static PyObject *Cluster_connect_uart(ClusterObject *self, PyObject *args)
{
	long a, ua, b, ub;
	if (!PyArg_ParseTuple(args, "llll", &a, &ua, &b, &ub))
		return NULL;
	m162_usart_t *sa = get_usart(self, a, ua), *sb = sa ? get_usart(self, b, ub) : NULL;
	if (!sa || !sb)
		return NULL;
	if (!sa->mcu->is_m162 || !sb->mcu->is_m162) {
		PyErr_SetString(PyExc_ValueError, "connect_uart needs atmega162 cores on both ends");
		return NULL;
	}
	if (sa == sb) {
		PyErr_SetString(PyExc_ValueError, "cannot wire a USART to itself");
		return NULL;
	}
	if ((sa->peer && sa->peer != sb) || (sb->peer && sb->peer != sa)) {
		PyErr_SetString(PyExc_ValueError, "USART already wired to another one");
		return NULL;
	}
	cluster_connect(self->c, (int)a, (int)ua, (int)b, (int)ub);
	Py_RETURN_NONE;
}

static PyObject *Cluster_watch_uart(ClusterObject *self, PyObject *args)
{
	long m, u;
	if (!PyArg_ParseTuple(args, "ll", &m, &u))
		return NULL;
	if (!get_usart(self, m, u))
		return NULL;
	cluster_watch(self->c, (int)m, (int)u);
	Py_RETURN_NONE;
}

static PyObject *Cluster_run(ClusterObject *self, PyObject *args)
{
	unsigned long long until;
	if (!PyArg_ParseTuple(args, "K", &until))
		return NULL;
	if (idle_or_fail(self) < 0)
		return NULL;
	/* No Python object is touched until the GIL is back: cluster_run is
	 * plain C on self->c, which the running flag keeps other threads off. */
	uint64_t reached;
	self->running = 1;
	Py_BEGIN_ALLOW_THREADS
	reached = cluster_run(self->c, until);
	Py_END_ALLOW_THREADS
	self->running = 0;
	return PyLong_FromUnsignedLongLong(reached);
}

static PyObject *Cluster_uart_take(ClusterObject *self, PyObject *args)
{
	long m, u;
	if (!PyArg_ParseTuple(args, "ll", &m, &u))
		return NULL;
	m162_usart_t *s = get_usart(self, m, u);
	if (!s)
		return NULL;
	if (!s->watched) {
		PyErr_Format(PyExc_ValueError, "USART %ld of MCU %ld is not watched: call watch_uart",
				u, m);
		return NULL;
	}
	PyObject *list = PyList_New(0);
	if (!list)
		return NULL;
	uint64_t now = self->c->cycle;
	while (s->take_pos < s->log_len && s->log[s->take_pos].end <= now) {
		m162_txrec_t *r = &s->log[s->take_pos];
		PyObject *t = Py_BuildValue("(KKi)", (unsigned long long)r->start,
				(unsigned long long)r->end, (int)r->byte);
		if (!t || PyList_Append(list, t) < 0) {
			Py_XDECREF(t);
			Py_DECREF(list);
			return NULL;
		}
		Py_DECREF(t);
		s->take_pos++;
	}
	if (s->notified_pos < s->take_pos)
		s->notified_pos = s->take_pos;
	return list;
}

static PyObject *Cluster_uart_put(ClusterObject *self, PyObject *args, PyObject *kw)
{
	static char *kwlist[] = { "mcu", "uart", "byte", "framing_error", NULL };
	long m, u, byte;
	int fe = 0;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "lll|p", kwlist, &m, &u, &byte, &fe))
		return NULL;
	m162_usart_t *s = get_usart(self, m, u);
	if (!s)
		return NULL;
	if (!s->mcu->is_m162) {
		PyErr_SetString(PyExc_ValueError, "uart_put needs an atmega162 core");
		return NULL;
	}
	if (byte < 0 || byte > 255) {
		PyErr_Format(PyExc_ValueError, "byte %ld out of range 0..255", byte);
		return NULL;
	}
	uint16_t v = (uint16_t)byte | (fe ? UART_INPUT_FE : 0);
	return PyBool_FromLong(m162_usart_put(s, v));
}

static PyObject *Cluster_uart_drop(ClusterObject *self, PyObject *args)
{
	long m, u;
	if (!PyArg_ParseTuple(args, "ll", &m, &u))
		return NULL;
	m162_usart_t *s = get_usart(self, m, u);
	if (!s)
		return NULL;
	s->rx_dropped++;
	Py_RETURN_NONE;
}

static PyObject *Cluster_uart_config(ClusterObject *self, PyObject *args)
{
	long m, u;
	if (!PyArg_ParseTuple(args, "ll", &m, &u))
		return NULL;
	m162_usart_t *s = get_usart(self, m, u);
	if (!s)
		return NULL;
	if (!s->mcu->is_m162) {
		PyErr_SetString(PyExc_ValueError, "uart_config needs an atmega162 core");
		return NULL;
	}
	double baud;
	int db, sb, rxen, txen;
	char parity;
	m162_usart_config(s, &baud, &db, &parity, &sb, &rxen, &txen);
	char par[2] = { parity, 0 };
	return Py_BuildValue("{s:d,s:i,s:s,s:i,s:O,s:O,s:k,s:k,s:K,s:K}", "baud", baud, "data_bits",
			db, "parity", par, "stop_bits", sb, "rxen", rxen ? Py_True : Py_False, "txen",
			txen ? Py_True : Py_False, "frame_cycles", (unsigned long)s->frame_cycles,
			"bit_cycles", (unsigned long)s->bit_cycles,
			"rx_dropped", (unsigned long long)s->rx_dropped,
			"rx_log_lost", (unsigned long long)s->rx_log_lost);
}

static PyObject *Cluster_set_clock(ClusterObject *self, PyObject *args)
{
	long m;
	double hz;
	if (!PyArg_ParseTuple(args, "ld", &m, &hz))
		return NULL;
	m162_t *mc = get_mcu(self, m);
	if (!mc)
		return NULL;
	if (!(hz >= 1000.0 && hz <= 100e6)) {
		PyErr_Format(PyExc_ValueError, "clock %g Hz outside 1 kHz..100 MHz", hz);
		return NULL;
	}
	cluster_set_clock(self->c, (int)m, (uint32_t)(hz + 0.5));
	Py_RETURN_NONE;
}

static PyObject *Cluster_clock(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	return mc ? PyLong_FromUnsignedLong(mc->clock.hz) : NULL;
}

static PyObject *Cluster_changed(ClusterObject *self, PyObject *noargs)
{
	(void)noargs;
	if (idle_or_fail(self) < 0)
		return NULL;
	PyObject *list = PyList_New(0);
	if (!list)
		return NULL;
	for (int i = 0; i < self->c->n; i++) {
		m162_t *m = self->c->mcu[i];
		if (!m->changed)
			continue;
		m->changed = 0;
		PyObject *v = PyLong_FromLong(i);
		if (!v || PyList_Append(list, v) < 0) {
			Py_XDECREF(v);
			Py_DECREF(list);
			return NULL;
		}
		Py_DECREF(v);
	}
	return list;
}

static PyObject *Cluster_port(ClusterObject *self, PyObject *args)
{
	long m;
	const char *name;
	if (!PyArg_ParseTuple(args, "ls", &m, &name))
		return NULL;
	m162_t *mc = get_m162(self, m);
	int p = mc ? port_index(name) : -1;
	if (p < 0)
		return NULL;
	uint8_t *d = mc->avr->data;
	uint8_t ddr = d[m162_port_regs[p][1]], port = d[m162_port_regs[p][2]];
	uint8_t pin = (d[m162_port_regs[p][0]] & ~ddr) | (port & ddr);
	return Py_BuildValue("(iii)", ddr, port, pin);
}

static PyObject *Cluster_set_input(ClusterObject *self, PyObject *args)
{
	long m, mask, value;
	const char *name;
	if (!PyArg_ParseTuple(args, "lsll", &m, &name, &mask, &value))
		return NULL;
	m162_t *mc = get_m162(self, m);
	int p = mc ? port_index(name) : -1;
	if (p < 0)
		return NULL;
	if (mask < 0 || mask > 255 || value < 0 || value > 255) {
		PyErr_SetString(PyExc_ValueError, "mask and value must be 0..255");
		return NULL;
	}
	m162_drive_input(mc, p, (uint8_t)mask, (uint8_t)value);
	Py_RETURN_NONE;
}

static PyObject *Cluster_pin_log(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	if (!mc)
		return NULL;
	PyObject *list = PyList_New((Py_ssize_t)mc->pinlog_len);
	if (!list)
		return NULL;
	for (size_t i = 0; i < mc->pinlog_len; i++) {
		char nm[2] = { mc->pinlog[i].port, 0 };
		PyObject *t = Py_BuildValue("(Ksi)", (unsigned long long)mc->pinlog[i].cycle, nm,
				(int)mc->pinlog[i].value);
		if (!t) {
			Py_DECREF(list);
			return NULL;
		}
		PyList_SET_ITEM(list, (Py_ssize_t)i, t);
	}
	mc->pinlog_len = 0;
	return list;
}

static PyObject *Cluster_resets(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	if (!mc)
		return NULL;
	PyObject *list = PyList_New((Py_ssize_t)mc->n_resets);
	if (!list)
		return NULL;
	for (size_t i = 0; i < mc->n_resets; i++) {
		PyObject *v = PyLong_FromUnsignedLongLong((unsigned long long)mc->resets[i]);
		if (!v) {
			Py_DECREF(list);
			return NULL;
		}
		PyList_SET_ITEM(list, (Py_ssize_t)i, v);
	}
	mc->n_resets = 0;
	return list;
}

static PyObject *Cluster_uart_rx_log(ClusterObject *self, PyObject *args)
{
	long m, u;
	if (!PyArg_ParseTuple(args, "ll", &m, &u))
		return NULL;
	m162_usart_t *s = get_usart(self, m, u);
	if (!s)
		return NULL;
	PyObject *list = PyList_New((Py_ssize_t)s->rx_log_len);
	if (!list)
		return NULL;
	for (size_t i = 0; i < s->rx_log_len; i++) {
		PyObject *t = Py_BuildValue("(KO)", (unsigned long long)s->rx_log[i].cycle,
				s->rx_log[i].on ? Py_True : Py_False);
		if (!t) {
			Py_DECREF(list);
			return NULL;
		}
		PyList_SET_ITEM(list, (Py_ssize_t)i, t);
	}
	s->rx_log_len = 0;
	return list;
}

static PyObject *Cluster_state(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	return mc ? PyUnicode_FromString(m162_state_name(mc->avr->state)) : NULL;
}

static PyObject *Cluster_last_error(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	return mc ? PyUnicode_FromString(mc->last_error) : NULL;
}

static PyObject *Cluster_name(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	return mc ? PyUnicode_FromString(mc->name) : NULL;
}

static PyObject *Cluster_mcu_cycle(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	return mc ? PyLong_FromUnsignedLongLong(mc->avr->cycle) : NULL;
}

static PyObject *Cluster_sleep_stats(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	if (!mc)
		return NULL;
	return Py_BuildValue("{sKsKsK}", "cycle", (unsigned long long)mc->avr->cycle,
			"slept_cycles", (unsigned long long)mc->slept_cycles,
			"sleeps", (unsigned long long)mc->sleeps);
}

static PyObject *Cluster_reset(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	if (!mc)
		return NULL;
	m162_reset(mc);
	Py_RETURN_NONE;
}

static PyObject *Cluster_read_data(ClusterObject *self, PyObject *args)
{
	long m, addr, len;
	if (!PyArg_ParseTuple(args, "lll", &m, &addr, &len))
		return NULL;
	m162_t *mc = get_mcu(self, m);
	if (!mc)
		return NULL;
	if (addr < 0 || len < 0 || addr + len > (long)mc->avr->ramend + 1) {
		PyErr_Format(PyExc_ValueError, "data range 0x%lx+%ld outside 0..0x%x", addr, len,
				mc->avr->ramend);
		return NULL;
	}
	return PyBytes_FromStringAndSize((const char *)mc->avr->data + addr, len);
}

static PyObject *Cluster_read_flash(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	return mc ? PyBytes_FromStringAndSize((const char *)mc->avr->flash, mc->avr->flashend + 1)
		  : NULL;
}

static PyObject *Cluster_write_flash(ClusterObject *self, PyObject *args)
{
	long m;
	Py_buffer buf;
	if (!PyArg_ParseTuple(args, "ly*", &m, &buf))
		return NULL;
	m162_t *mc = get_mcu(self, m);
	if (!mc) {
		PyBuffer_Release(&buf);
		return NULL;
	}
	uint32_t size = mc->avr->flashend + 1;
	if ((size_t)buf.len > size) {
		PyErr_Format(PyExc_ValueError, "image is %zd bytes, flash holds %u", buf.len, size);
		PyBuffer_Release(&buf);
		return NULL;
	}
	/* the whole flash is replaced: what the image does not cover is erased */
	memset(mc->avr->flash, 0xFF, size);
	memcpy(mc->avr->flash, buf.buf, buf.len);
	mc->avr->codeend = size;
	PyBuffer_Release(&buf);
	Py_RETURN_NONE;
}

static uint8_t *eeprom_bytes(m162_t *mc, uint32_t *size)
{
	*size = mc->mcu.eeprom.size;
	return mc->mcu.eeprom.eeprom;
}

static PyObject *Cluster_read_eeprom(ClusterObject *self, PyObject *args)
{
	m162_t *mc = m162_arg(self, args);
	if (!mc)
		return NULL;
	uint32_t size;
	uint8_t *ee = eeprom_bytes(mc, &size);
	return PyBytes_FromStringAndSize((const char *)ee, size);
}

static PyObject *Cluster_write_eeprom(ClusterObject *self, PyObject *args)
{
	long m, addr;
	Py_buffer buf;
	if (!PyArg_ParseTuple(args, "lly*", &m, &addr, &buf))
		return NULL;
	m162_t *mc = get_m162(self, m);
	if (!mc) {
		PyBuffer_Release(&buf);
		return NULL;
	}
	uint32_t size;
	uint8_t *ee = eeprom_bytes(mc, &size);
	if (addr < 0 || addr + buf.len > (Py_ssize_t)size) {
		PyErr_Format(PyExc_ValueError, "EEPROM range %ld+%zd outside 0..%u", addr, buf.len,
				size - 1);
		PyBuffer_Release(&buf);
		return NULL;
	}
	memcpy(ee + addr, buf.buf, buf.len);
	PyBuffer_Release(&buf);
	Py_RETURN_NONE;
}

static PyObject *Cluster_fuses(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	return mc ? Py_BuildValue("(iii)", mc->avr->fuse[0], mc->avr->fuse[1], mc->avr->fuse[2])
		  : NULL;
}

static PyObject *Cluster_set_fuses(ClusterObject *self, PyObject *args)
{
	long m, lo, hi, ext;
	if (!PyArg_ParseTuple(args, "llll", &m, &lo, &hi, &ext))
		return NULL;
	m162_t *mc = get_mcu(self, m);
	if (!mc)
		return NULL;
	if (lo < 0 || lo > 255 || hi < 0 || hi > 255 || ext < 0 || ext > 255) {
		PyErr_SetString(PyExc_ValueError, "fuse bytes must be 0..255");
		return NULL;
	}
	mc->avr->fuse[0] = (uint8_t)lo;
	mc->avr->fuse[1] = (uint8_t)hi;
	mc->avr->fuse[2] = (uint8_t)ext;
	Py_RETURN_NONE;
}

static PyObject *Cluster_signature(ClusterObject *self, PyObject *args)
{
	m162_t *mc = mcu_arg(self, args);
	return mc ? PyBytes_FromStringAndSize((const char *)mc->avr->signature, 3) : NULL;
}

static PyObject *Cluster_set_signature(ClusterObject *self, PyObject *args)
{
	long m;
	Py_buffer buf;
	if (!PyArg_ParseTuple(args, "ly*", &m, &buf))
		return NULL;
	m162_t *mc = get_mcu(self, m);
	if (!mc || buf.len != 3) {
		if (mc)
			PyErr_Format(PyExc_ValueError, "signature is 3 bytes, got %zd", buf.len);
		PyBuffer_Release(&buf);
		return NULL;
	}
	memcpy(mc->avr->signature, buf.buf, 3);
	PyBuffer_Release(&buf);
	Py_RETURN_NONE;
}

/* ---------------------------------------------------------------- */
/* RF12 radios (rf12_part.h) */

static PyObject *airbyte_tuple(const rf12_airbyte_t *b)
{
	return Py_BuildValue("(KKiO(iii))", (unsigned long long)b->start,
			(unsigned long long)b->end, b->byte, b->cut ? Py_True : Py_False,
			b->channel.band, b->channel.freq, b->channel.rate);
}

static rf12_t *radio_arg(ClusterObject *self, PyObject *args)
{
	m162_t *mc = m162_arg(self, args);
	if (mc && !mc->rf12) {
		PyErr_Format(PyExc_ValueError, "MCU %s has no RF12 radio (attach_rf12 first)", mc->name);
		return NULL;
	}
	return mc ? mc->rf12 : NULL;
}

static PyObject *Cluster_attach_rf12(ClusterObject *self, PyObject *args)
{
	long m;
	const char *spi, *irq_port;
	rf12_pins_t p;
	if (!PyArg_ParseTuple(args, "l(siiii)(si)", &m, &spi, &p.sel, &p.sdi, &p.sdo, &p.sck,
			&irq_port, &p.irq))
		return NULL;
	m162_t *mc = get_m162(self, m);
	p.spi_port = mc ? port_index(spi) : -1;
	p.irq_port = p.spi_port >= 0 ? port_index(irq_port) : -1;
	if (p.irq_port < 0)
		return NULL;
	int bits[] = { p.sel, p.sdi, p.sdo, p.sck, p.irq };
	for (size_t i = 0; i < sizeof bits / sizeof bits[0]; i++)
		if (bits[i] < 0 || bits[i] > 7) {
			PyErr_SetString(PyExc_ValueError, "pin bits must be 0..7");
			return NULL;
		}
	if (mc->rf12) {
		PyErr_Format(PyExc_ValueError, "MCU %s already has an RF12 radio", mc->name);
		return NULL;
	}
	if (!rf12_attach(mc, p))
		return PyErr_NoMemory();
	Py_RETURN_NONE;
}

static PyObject *Cluster_radio_take(ClusterObject *self, PyObject *args)
{
	rf12_t *r = radio_arg(self, args);
	if (!r)
		return NULL;
	rf12_airbyte_t buf[RF12_LOG_SIZE];
	int n = rf12_take(r, buf, RF12_LOG_SIZE);
	PyObject *list = PyList_New(n);
	for (int i = 0; list && i < n; i++) {
		PyObject *t = airbyte_tuple(&buf[i]);
		if (!t) {
			Py_DECREF(list);
			return NULL;
		}
		PyList_SET_ITEM(list, i, t);
	}
	return list;
}

static PyObject *Cluster_radio_carrier(ClusterObject *self, PyObject *args)
{
	rf12_t *r = radio_arg(self, args);
	if (!r)
		return NULL;
	rf12_airbyte_t b;
	if (!rf12_carrier(r, &b))
		Py_RETURN_NONE;
	return airbyte_tuple(&b);
}

static PyObject *Cluster_radio_deliver(ClusterObject *self, PyObject *args)
{
	long m, byte;
	unsigned long long due;
	if (!PyArg_ParseTuple(args, "lKl", &m, &due, &byte))
		return NULL;
	PyObject *mt = Py_BuildValue("(l)", m);
	rf12_t *r = mt ? radio_arg(self, mt) : NULL;
	Py_XDECREF(mt);
	if (!r)
		return NULL;
	if (byte < 0 || byte > 255) {
		PyErr_SetString(PyExc_ValueError, "byte must be 0..255");
		return NULL;
	}
	rf12_deliver(r, due, (uint8_t)byte);
	Py_RETURN_NONE;
}

static PyObject *Cluster_radio_state(ClusterObject *self, PyObject *args)
{
	rf12_t *r = radio_arg(self, args);
	if (!r)
		return NULL;
	return Py_BuildValue("{s:O,s:O,s:(iii),s:K,s:K}",
			"receiving", rf12_receiving(r) ? Py_True : Py_False,
			"transmitting", r->tx_on ? Py_True : Py_False,
			"channel", r->channel.band, r->channel.freq, r->channel.rate,
			"rx_dropped", (unsigned long long)r->rx_dropped,
			"log_dropped", (unsigned long long)r->log_dropped);
}


/* ---------------------------------------------------------------- */
/* The IR medium in C (ir_medium.h) */

static ir_port_t *ir_arg(ClusterObject *self, long m)
{
	m162_t *mc = get_m162(self, m);
	if (mc && !mc->ir) {
		PyErr_Format(PyExc_ValueError, "MCU %s is not on the IR medium (ir_attach first)",
				mc->name);
		return NULL;
	}
	return mc ? mc->ir : NULL;
}

static PyObject *Cluster_ir_attach(ClusterObject *self, PyObject *args)
{
	long m, u;
	const char *port;
	int bits[3];
	if (!PyArg_ParseTuple(args, "lls(iii)", &m, &u, &port, &bits[0], &bits[1], &bits[2]))
		return NULL;
	m162_usart_t *s = get_usart(self, m, u);
	int p = s ? port_index(port) : -1;
	if (p < 0)
		return NULL;
	if (!s->mcu->is_m162) {
		PyErr_SetString(PyExc_ValueError, "ir_attach needs an atmega162 core");
		return NULL;
	}
	uint8_t sel[3];
	for (int i = 0; i < 3; i++) {
		if (bits[i] < 0 || bits[i] > 7) {
			PyErr_SetString(PyExc_ValueError, "selector bits must be 0..7");
			return NULL;
		}
		sel[i] = (uint8_t)bits[i];
	}
	if (ir_attach(self->c, (int)m, (int)u, p, sel) < 0)
		return PyErr_NoMemory();
	Py_RETURN_NONE;
}

static PyObject *Cluster_ir_routes(ClusterObject *self, PyObject *args)
{
	long m;
	PyObject *seq;
	if (!PyArg_ParseTuple(args, "lO", &m, &seq))
		return NULL;
	if (!ir_arg(self, m))
		return NULL;
	PyObject *fast = PySequence_Fast(seq, "routes must be a sequence of 8 (kind, target, y)");
	if (!fast)
		return NULL;
	if (PySequence_Fast_GET_SIZE(fast) != 8) {
		Py_DECREF(fast);
		PyErr_SetString(PyExc_ValueError, "routes: one per selector index, 8 in all");
		return NULL;
	}
	ir_route_t routes[8];
	for (int y = 0; y < 8; y++) {
		PyObject *item = PySequence_Fast_GET_ITEM(fast, y);
		const char *kind;
		int target = -1, need = 0;
		if (!PyArg_ParseTuple(item, "s|ii", &kind, &target, &need)) {
			Py_DECREF(fast);
			return NULL;
		}
		if (!strcmp(kind, "none")) {
			routes[y] = (ir_route_t){ IR_ROUTE_NONE, -1, 0 };
		} else if (!strcmp(kind, "pc")) {
			routes[y] = (ir_route_t){ IR_ROUTE_PC, -1, 0 };
		} else if (!strcmp(kind, "mcu") && target >= 0 && target < self->c->n &&
				self->c->mcu[target]->ir && need >= 0 && need < 8) {
			routes[y] = (ir_route_t){ IR_ROUTE_MODULE, target, need };
		} else {
			Py_DECREF(fast);
			PyErr_Format(PyExc_ValueError, "route %d: ('none',), ('pc',) or ('mcu', "
					"attached MCU, selector index 0..7), not %R", y, item);
			return NULL;
		}
	}
	Py_DECREF(fast);
	ir_set_routes(self->c, (int)m, routes);
	Py_RETURN_NONE;
}

static PyObject *Cluster_ir_seed(ClusterObject *self, PyObject *args)
{
	unsigned long long seed;
	if (!PyArg_ParseTuple(args, "K", &seed))
		return NULL;
	ir_set_seed(self->c, seed);
	Py_RETURN_NONE;
}

static PyObject *Cluster_ir_send_from_pc(ClusterObject *self, PyObject *args, PyObject *kw)
{
	static char *kwlist[] = { "start", "end", "byte", "data_bits", "parity", "stop_bits", NULL };
	unsigned long long start, end;
	long byte;
	int db = 8, sb = 1;
	const char *parity = "N";
	if (!PyArg_ParseTupleAndKeywords(args, kw, "KKl|isi", kwlist, &start, &end, &byte, &db,
			&parity, &sb))
		return NULL;
	int upm = !strcmp(parity, "N") ? 0 : !strcmp(parity, "E") ? 2 : !strcmp(parity, "O") ? 3 : -1;
	if (byte < 0 || byte > 255 || end <= start || db < 5 || db > 9 || sb < 1 || sb > 2 ||
			upm < 0) {
		PyErr_SetString(PyExc_ValueError, "ir_send_from_pc: byte 0..255, end after start, "
				"5..9 data bits, parity N/E/O, 1 or 2 stop bits");
		return NULL;
	}
	ir_send_from_pc(self->c, start, end, (uint8_t)byte, (uint8_t)(db | upm << 4 | sb << 6));
	Py_RETURN_NONE;
}

static int by_end(const void *a, const void *b)
{
	const long long *x = a, *y = b; /* (end, start, mcu, byte) */
	for (int i = 0; i < 3; i++)
		if (x[i] != y[i])
			return x[i] < y[i] ? -1 : 1;
	return 0;
}

static PyObject *Cluster_ir_take_pc(ClusterObject *self, PyObject *noargs)
{
	(void)noargs;
	size_t n = 0, cap = 0;
	long long (*rows)[4] = NULL;
	for (int i = 0; i < self->c->n; i++) {
		ir_port_t *p = self->c->mcu[i]->ir;
		if (!p)
			continue;
		ir_pcbyte_t buf[64];
		size_t k;
		while ((k = ir_take_pc(p, self->c->cycle, buf, 64)) > 0) {
			if (n + k > cap) {
				cap = (n + k) * 2;
				void *r = realloc(rows, cap * sizeof *rows);
				if (!r) {
					free(rows);
					return PyErr_NoMemory();
				}
				rows = r;
			}
			for (size_t j = 0; j < k; j++) {
				rows[n][0] = (long long)buf[j].end;
				rows[n][1] = (long long)buf[j].start;
				rows[n][2] = i;
				rows[n][3] = buf[j].byte;
				n++;
			}
		}
	}
	if (n)
		qsort(rows, n, sizeof *rows, by_end);
	PyObject *list = PyList_New((Py_ssize_t)n);
	for (size_t j = 0; list && j < n; j++) {
		PyObject *t = Py_BuildValue("(lKKi)", (long)rows[j][2], (unsigned long long)rows[j][1],
				(unsigned long long)rows[j][0], (int)rows[j][3]);
		if (!t) {
			Py_CLEAR(list);
			break;
		}
		PyList_SET_ITEM(list, (Py_ssize_t)j, t);
	}
	free(rows);
	return list;
}

static int event_order(const void *a, const void *b)
{
	const ir_event_t *x = *(ir_event_t *const *)a, *y = *(ir_event_t *const *)b;
	if (x->end != y->end)
		return x->end < y->end ? -1 : 1;
	if (x->receiver != y->receiver)
		return x->receiver < y->receiver ? -1 : 1;
	return x->seq < y->seq ? -1 : x->seq > y->seq;
}

static PyObject *Cluster_ir_events(ClusterObject *self, PyObject *noargs)
{
	(void)noargs;
	static const char *names[] = { "", "ir-collision", "ir-dropped", "ir-garbled" };
	size_t n = 0;
	for (int i = 0; i < self->c->n; i++)
		if (self->c->mcu[i]->ir)
			n += self->c->mcu[i]->ir->n_events;
	PyObject *list = PyList_New(0);
	if (!list || !n)
		return list;
	ir_event_t **all = malloc(n * sizeof *all);
	if (!all) {
		Py_DECREF(list);
		return PyErr_NoMemory();
	}
	size_t k = 0;
	for (int i = 0; i < self->c->n; i++) {
		ir_port_t *p = self->c->mcu[i]->ir;
		for (size_t j = 0; p && j < p->n_events; j++)
			all[k++] = &p->events[j];
	}
	qsort(all, n, sizeof *all, event_order);
	for (size_t j = 0; j < n; j++) {
		ir_event_t *e = all[j];
		PyObject *others = PyTuple_New(e->n_others);
		for (int o = 0; others && o < e->n_others; o++)
			PyTuple_SET_ITEM(others, o, PyLong_FromLong(e->others[o]));
		PyObject *t = others ? Py_BuildValue("(sKiiiN)", names[e->kind],
				(unsigned long long)e->end, e->sender, e->receiver, (int)e->byte, others)
				: NULL;
		if (!t || PyList_Append(list, t) < 0) {
			Py_XDECREF(t);
			Py_CLEAR(list);
			break;
		}
		Py_DECREF(t);
	}
	free(all);
	for (int i = 0; i < self->c->n; i++)
		if (self->c->mcu[i]->ir)
			self->c->mcu[i]->ir->n_events = 0;
	return list;
}

static PyObject *Cluster_ir_state(ClusterObject *self, PyObject *args)
{
	long m;
	if (!PyArg_ParseTuple(args, "l", &m))
		return NULL;
	ir_port_t *p = ir_arg(self, m);
	if (!p)
		return NULL;
	static const char *kinds[] = { "none", "pc", "mcu" };
	PyObject *routes = PyList_New(8);
	for (int y = 0; routes && y < 8; y++) {
		const ir_route_t *r = &p->routes[y];
		PyObject *t = r->kind == IR_ROUTE_MODULE
			? Py_BuildValue("(sii)", kinds[r->kind], r->target, r->need_y)
			: Py_BuildValue("(s)", kinds[r->kind]);
		if (!t) {
			Py_CLEAR(routes);
			break;
		}
		PyList_SET_ITEM(routes, y, t);
	}
	if (!routes)
		return NULL;
	return Py_BuildValue("{s:i,s:K,s:n,s:N}", "in_flight", p->inbox_len, "overflow",
			(unsigned long long)p->overflow, "for_pc", (Py_ssize_t)p->n_pc, "routes", routes);
}

static PyObject *Cluster_wake_on_pins(ClusterObject *self, PyObject *args)
{
	long m;
	const char *ports;
	if (!PyArg_ParseTuple(args, "ls", &m, &ports))
		return NULL;
	m162_t *mc = get_m162(self, m);
	if (!mc)
		return NULL;
	uint8_t mask = 0;
	for (const char *q = ports; *q; q++) {
		char one[2] = { *q, 0 };
		int p = port_index(one);
		if (p < 0)
			return NULL;
		mask |= (uint8_t)(1u << p);
	}
	mc->wake_ports = mask;
	Py_RETURN_NONE;
}

static PyMethodDef Cluster_methods[] = {
	{ "add_mcu", (PyCFunction)(void (*)(void))Cluster_add_mcu, METH_VARARGS | METH_KEYWORDS,
		"add_mcu(elf_path, name, core='atmega162') -> index: load an ELF on a new MCU" },
	{ "connect_uart", (PyCFunction)Cluster_connect_uart, METH_VARARGS,
		"connect_uart(a, uart_a, b, uart_b): full-duplex wire between two USARTs" },
	{ "watch_uart", (PyCFunction)Cluster_watch_uart, METH_VARARGS,
		"watch_uart(mcu, uart): queue this USART's transmitted bytes for uart_take" },
	{ "run", (PyCFunction)Cluster_run, METH_VARARGS,
		"run(until_cycle) -> cycle reached; returns early after a watched byte" },
	{ "uart_take", (PyCFunction)Cluster_uart_take, METH_VARARGS,
		"uart_take(mcu, uart) -> [(start_cycle, end_cycle, byte)]" },
	{ "uart_put", (PyCFunction)(void (*)(void))Cluster_uart_put, METH_VARARGS | METH_KEYWORDS,
		"uart_put(mcu, uart, byte, framing_error=False) -> False if dropped" },
	{ "uart_drop", (PyCFunction)Cluster_uart_drop, METH_VARARGS,
		"uart_drop(mcu, uart): a byte reached the receiver while it was off (the Python IR "
		"medium): counted in rx_dropped, as uart_put counts one; nothing is received" },
	{ "uart_config", (PyCFunction)Cluster_uart_config, METH_VARARGS,
		"uart_config(mcu, uart) -> dict of the USART's present configuration" },
	{ "port", (PyCFunction)Cluster_port, METH_VARARGS, "port(mcu, 'A'..'E') -> (DDR, PORT, PIN)" },
	{ "set_clock", (PyCFunction)Cluster_set_clock, METH_VARARGS,
		"set_clock(mcu, hz): run this MCU on its own clock from now on" },
	{ "clock", (PyCFunction)Cluster_clock, METH_VARARGS, "clock(mcu) -> its clock in Hz" },
	{ "changed", (PyCFunction)Cluster_changed, METH_NOARGS,
		"changed() -> MCUs with new pin-log records or watched bytes since the last call" },
	{ "attach_rf12", (PyCFunction)Cluster_attach_rf12, METH_VARARGS,
		"attach_rf12(mcu, (port, nsel, sdi, sdo, sck), (port, nirq)): an RF12 radio on these pins" },
	{ "radio_take", (PyCFunction)Cluster_radio_take, METH_VARARGS,
		"radio_take(mcu) -> [(start, end, byte, cut, (band, freq, rate))] bytes that left the air" },
	{ "radio_carrier", (PyCFunction)Cluster_radio_carrier, METH_VARARGS,
		"radio_carrier(mcu) -> the byte on the air now, as radio_take's records, or None" },
	{ "radio_deliver", (PyCFunction)Cluster_radio_deliver, METH_VARARGS,
		"radio_deliver(mcu, due_cycle, byte): a byte from the air, complete at due_cycle" },
	{ "radio_state", (PyCFunction)Cluster_radio_state, METH_VARARGS,
		"radio_state(mcu) -> {receiving, transmitting, channel, rx_dropped, log_dropped}" },
	{ "ir_attach", (PyCFunction)Cluster_ir_attach, METH_VARARGS,
		"ir_attach(mcu, uart, port, (bit_a, bit_b, bit_c)): put this USART on the C IR medium, "
		"its selector lines A, B, C on these bits of port" },
	{ "ir_routes", (PyCFunction)Cluster_ir_routes, METH_VARARGS,
		"ir_routes(mcu, routes): per selector index 0..7 ('none',), ('pc',) or "
		"('mcu', receiver, receiver's selector index that faces this MCU)" },
	{ "ir_seed", (PyCFunction)Cluster_ir_seed, METH_VARARGS,
		"ir_seed(seed): seed the receivers' garbage for mismatched frames" },
	{ "ir_send_from_pc", (PyCFunction)(void (*)(void))Cluster_ir_send_from_pc,
		METH_VARARGS | METH_KEYWORDS,
		"ir_send_from_pc(start, end, byte, data_bits=8, parity='N', stop_bits=1): a byte of "
		"the PC's transceiver, to every board on the centre channel" },
	{ "ir_take_pc", (PyCFunction)Cluster_ir_take_pc, METH_NOARGS,
		"ir_take_pc() -> [(mcu, start, end, byte)] bytes sent on the centre channel that ended" },
	{ "ir_events", (PyCFunction)Cluster_ir_events, METH_NOARGS,
		"ir_events() -> [(name, end, sender, receiver, byte, others)] since the last call "
		"(sender -1: the PC)" },
	{ "ir_state", (PyCFunction)Cluster_ir_state, METH_VARARGS,
		"ir_state(mcu) -> {in_flight, overflow, for_pc, routes}" },
	{ "wake_on_pins", (PyCFunction)Cluster_wake_on_pins, METH_VARARGS,
		"wake_on_pins(mcu, 'ABD'): run() returns at the boundary after these ports change" },
	{ "set_input", (PyCFunction)Cluster_set_input, METH_VARARGS,
		"set_input(mcu, port, mask, value): drive external levels on pins" },
	{ "resets", (PyCFunction)Cluster_resets, METH_VARARGS,
		"resets(mcu) -> [cycle] of the MCU's resets since the last call (at most the last 64)" },
	{ "uart_rx_log", (PyCFunction)Cluster_uart_rx_log, METH_VARARGS,
		"uart_rx_log(mcu, uart) -> [(cycle, on)] of the USART receiver's changes since the "
		"last call: RXEN set (True) or cleared, a reset (False); at most the last 64 "
		"(uart_config's rx_log_lost counts the older ones lost)" },
	{ "pin_log", (PyCFunction)Cluster_pin_log, METH_VARARGS,
		"pin_log(mcu) -> [(cycle, port, PORT value)] since the last call" },
	{ "state", (PyCFunction)Cluster_state, METH_VARARGS,
		"state(mcu) -> running|sleeping|crashed|done|stopped" },
	{ "last_error", (PyCFunction)Cluster_last_error, METH_VARARGS,
		"last_error(mcu) -> simavr's last error message for this MCU ('' if none)" },
	{ "name", (PyCFunction)Cluster_name, METH_VARARGS, "name(mcu) -> the name given to add_mcu" },
	{ "mcu_cycle", (PyCFunction)Cluster_mcu_cycle, METH_VARARGS,
		"mcu_cycle(mcu) -> this MCU's own cycle counter" },
	{ "sleep_stats", (PyCFunction)Cluster_sleep_stats, METH_VARARGS,
		"sleep_stats(mcu) -> {cycle, slept_cycles, sleeps}: own cycles, those spent asleep, "
		"SLEEP instructions that slept (awake cycles = cycle - slept_cycles)" },
	{ "reset", (PyCFunction)Cluster_reset, METH_VARARGS, "reset(mcu): external reset" },
	{ "read_data", (PyCFunction)Cluster_read_data, METH_VARARGS,
		"read_data(mcu, addr, length) -> bytes of the data space (registers, I/O, SRAM)" },
	{ "read_flash", (PyCFunction)Cluster_read_flash, METH_VARARGS, "read_flash(mcu) -> bytes" },
	{ "write_flash", (PyCFunction)Cluster_write_flash, METH_VARARGS,
		"write_flash(mcu, data): replace the flash (rest erased to 0xFF)" },
	{ "read_eeprom", (PyCFunction)Cluster_read_eeprom, METH_VARARGS, "read_eeprom(mcu) -> bytes" },
	{ "write_eeprom", (PyCFunction)Cluster_write_eeprom, METH_VARARGS,
		"write_eeprom(mcu, addr, data)" },
	{ "fuses", (PyCFunction)Cluster_fuses, METH_VARARGS, "fuses(mcu) -> (low, high, ext)" },
	{ "set_fuses", (PyCFunction)Cluster_set_fuses, METH_VARARGS, "set_fuses(mcu, low, high, ext)" },
	{ "signature", (PyCFunction)Cluster_signature, METH_VARARGS, "signature(mcu) -> 3 bytes" },
	{ "set_signature", (PyCFunction)Cluster_set_signature, METH_VARARGS,
		"set_signature(mcu, sig)" },
	{ NULL, NULL, 0, NULL },
};

static PyGetSetDef Cluster_getset[] = {
	{ "cycle", (getter)Cluster_get_cycle, NULL, "common simulated cycle", NULL },
	{ "quantum_cycles", (getter)Cluster_get_quantum, NULL, "lock-step quantum", NULL },
	{ "frequency", (getter)Cluster_get_frequency, NULL,
		"nominal clock, Hz: the unit of every cycle count (MCUs may run off it)", NULL },
	{ "baud_tolerance", (getter)Cluster_get_tolerance, NULL,
		"largest baud-rate mismatch a receiver takes, as a fraction", NULL },
	{ "mcu_count", (getter)Cluster_get_count, NULL, "number of MCUs", NULL },
	{ "threads", (getter)Cluster_get_threads, (setter)Cluster_set_threads,
		"threads that run each quantum (1 = the caller's only); the trace does not "
		"depend on it", NULL },
	{ "min_mcus_per_thread", (getter)Cluster_get_min_per_thread,
		(setter)Cluster_set_min_per_thread,
		"a quantum uses fewer threads if one would get fewer MCUs than this "
		"(default 32; 1 uses every thread)", NULL },
	{ NULL, NULL, NULL, NULL, NULL },
};

static PyTypeObject ClusterType = {
	PyVarObject_HEAD_INIT(NULL, 0)
	.tp_name = "hexbot.hil_sim._avr.Cluster",
	.tp_basicsize = sizeof(ClusterObject),
	.tp_flags = Py_TPFLAGS_DEFAULT,
	.tp_doc = "Several simulated ATmega162s advanced in lock-step quanta.",
	.tp_new = PyType_GenericNew,
	.tp_init = (initproc)Cluster_init,
	.tp_dealloc = (destructor)Cluster_dealloc,
	.tp_methods = Cluster_methods,
	.tp_getset = Cluster_getset,
};

static struct PyModuleDef avr_module = {
	PyModuleDef_HEAD_INIT, "_avr",
	"ATmega162 simulation on libsimavr, several MCUs in lock-step.", -1, NULL,
};

PyMODINIT_FUNC PyInit__avr(void)
{
	PyObject *timing = PyImport_ImportModule("hexbot.protocol.timing");
	if (!timing)
		return NULL;
	PyObject *tol = PyObject_GetAttrString(timing, "BAUD_TOLERANCE");
	Py_DECREF(timing);
	if (!tol)
		return NULL;
	baud_tolerance = PyFloat_AsDouble(tol);
	Py_DECREF(tol);
	if (PyErr_Occurred())
		return NULL;
	if (PyType_Ready(&ClusterType) < 0)
		return NULL;
	PyObject *m = PyModule_Create(&avr_module);
	if (!m)
		return NULL;
	Py_INCREF(&ClusterType);
	if (PyModule_AddObject(m, "Cluster", (PyObject *)&ClusterType) < 0) {
		Py_DECREF(&ClusterType);
		Py_DECREF(m);
		return NULL;
	}
	PyModule_AddStringConstant(m, "SIMAVR_VERSION", CONFIG_SIMAVR_VERSION);
	return m;
}
