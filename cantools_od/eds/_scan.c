/* The per-line work of reading a CiA 306 file (ini.py's `scan`), compiled: splitting a section's text
 * into lines and each line into an entry, a comment or a stray line. The reader's time on a large EDS
 * goes mostly here when it runs as Python, once per line.
 *
 * It does exactly what `ini._scan_python` does, which stays as the reference: the tests compare the two on
 * every real file and on generated text. Lines end at CR, LF or CRLF only. Blanks are space and tab.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#define MAX_LINE 255 /* CiA 306: characters in a line, without its end */

static PyObject *entry_type = NULL; /* ini.Entry, a NamedTuple of seven fields */

typedef struct {
    int kind;
    const void *data;
    PyObject *text;
} Text;

#define AT(t, i) PyUnicode_READ((t)->kind, (t)->data, (i))
#define BLANK(c) ((c) == ' ' || (c) == '\t')

/* An Entry as tuple.__new__(Entry, items) makes it: the subclass allocates, the items are set in place.
 * Steals `key` and `value`. */
static PyObject *new_entry(PyObject *key, PyObject *value, Py_ssize_t line, Py_ssize_t key_col,
                           Py_ssize_t value_col, PyObject *above, int spaced) {
    PyTypeObject *type = (PyTypeObject *)entry_type;
    PyObject *items[7] = {key,
                          value,
                          PyLong_FromSsize_t(line),
                          PyLong_FromSsize_t(key_col),
                          PyLong_FromSsize_t(value_col),
                          Py_NewRef(above),
                          Py_NewRef(spaced ? Py_True : Py_False)};
    PyObject *entry = NULL;
    if (items[2] && items[3] && items[4])
        entry = type->tp_alloc(type, 7);
    for (Py_ssize_t i = 0; i < 7; i++) {
        if (entry)
            PyTuple_SET_ITEM(entry, i, items[i]);
        else
            Py_XDECREF(items[i]);
    }
    return entry;
}

static int append_pair(PyObject *list, Py_ssize_t number, PyObject *item) {
    /* appends (number, item); steals `item` */
    if (!item)
        return -1;
    PyObject *pair = Py_BuildValue("(nN)", number, item);
    if (!pair)
        return -1;
    int failed = PyList_Append(list, pair);
    Py_DECREF(pair);
    return failed;
}

static int append_new(PyObject *list, PyObject *item) {
    /* appends `item` and drops the caller's reference */
    if (!item)
        return -1;
    int failed = PyList_Append(list, item);
    Py_DECREF(item);
    return failed;
}

typedef struct {
    PyObject *entries, *comments, *stray;
    int plain;
} Body;

/* One line of a section's body, without its end: [start, end). */
static int body_line(Text *t, Py_ssize_t start, Py_ssize_t end, Py_ssize_t line, Body *body) {
    Py_ssize_t first = start, last = end;
    while (first < last && BLANK(AT(t, first)))
        first++;
    while (last > first && BLANK(AT(t, last - 1)))
        last--;
    if (first == last)
        return 0;
    Py_UCS4 lead = AT(t, first);
    if (lead == ';' || lead == '#')
        return append_new(body->comments, PyUnicode_Substring(t->text, first, last));
    Py_ssize_t equals = first;
    while (equals < last && AT(t, equals) != '=')
        equals++;
    if (equals == last)
        return append_pair(body->stray, line, PyUnicode_Substring(t->text, first, last));
    PyObject *above;
    Py_ssize_t waiting = PyList_GET_SIZE(body->comments);
    if (waiting) {
        above = PyList_AsTuple(body->comments);
        if (!above || PyList_SetSlice(body->comments, 0, waiting, NULL) < 0) {
            Py_XDECREF(above);
            return -1;
        }
        body->plain = 0;
    } else {
        above = PyTuple_New(0);
        if (!above)
            return -1;
    }
    Py_ssize_t indent = first - start;
    if (indent)
        body->plain = 0;
    Py_ssize_t key_end = equals, value_start = equals + 1;
    while (key_end > first && BLANK(AT(t, key_end - 1)))
        key_end--;
    while (value_start < last && BLANK(AT(t, value_start)))
        value_start++;
    int spaced = key_end != equals || value_start != equals + 1;
    if (spaced)
        body->plain = 0;
    Py_ssize_t value_col = indent + (equals - first) + 2 + (value_start - equals - 1);
    PyObject *key = PyUnicode_Substring(t->text, first, key_end);
    PyObject *value = key ? PyUnicode_Substring(t->text, value_start, last) : NULL;
    if (!value) {
        Py_XDECREF(key);
        Py_DECREF(above);
        return -1;
    }
    PyObject *entry = new_entry(key, value, line, indent + 1, value_col, above, spaced);
    Py_DECREF(above);
    return append_new(body->entries, entry);
}

/* The header line [start, end) read as ini._HEADER does: (name stripped, column of "[", closed, the line). */
static PyObject *read_header(Text *t, Py_ssize_t start, Py_ssize_t end) {
    Py_ssize_t bracket = start;
    while (bracket < end && BLANK(AT(t, bracket)))
        bracket++;
    if (bracket == end || AT(t, bracket) != '[') {
        PyErr_SetString(PyExc_ValueError, "a section's text starts with its header line");
        return NULL;
    }
    Py_ssize_t close = bracket + 1;
    while (close < end && AT(t, close) != ']')
        close++;
    PyObject *between = PyUnicode_Substring(t->text, bracket + 1, close);
    if (!between)
        return NULL;
    PyObject *name = PyObject_CallMethod(between, "strip", NULL); /* str.strip: every kind of blank */
    Py_DECREF(between);
    if (!name)
        return NULL;
    PyObject *line = PyUnicode_Substring(t->text, start, end);
    if (!line) {
        Py_DECREF(name);
        return NULL;
    }
    return Py_BuildValue("(NnON)", name, bracket - start + 1, close < end ? Py_True : Py_False, line);
}

/* (keys, values) of the section's entries when all are written plainly on the lines right after the header,
 * else None (IniSection.plain). */
static PyObject *plain_keys(PyObject *entries, Py_ssize_t first, int plain) {
    Py_ssize_t count = PyList_GET_SIZE(entries);
    if (!plain || !count)
        Py_RETURN_NONE;
    PyObject *last_line = PyTuple_GET_ITEM(PyList_GET_ITEM(entries, count - 1), 2);
    Py_ssize_t last = PyLong_AsSsize_t(last_line);
    if (last == -1 && PyErr_Occurred())
        return NULL;
    if (last - first != count)
        Py_RETURN_NONE;
    PyObject *keys = PyTuple_New(count), *values = PyTuple_New(count);
    if (!keys || !values) {
        Py_XDECREF(keys);
        Py_XDECREF(values);
        return NULL;
    }
    for (Py_ssize_t i = 0; i < count; i++) {
        PyObject *entry = PyList_GET_ITEM(entries, i);
        PyTuple_SET_ITEM(keys, i, Py_NewRef(PyTuple_GET_ITEM(entry, 0)));
        PyTuple_SET_ITEM(values, i, Py_NewRef(PyTuple_GET_ITEM(entry, 1)));
    }
    return Py_BuildValue("(NN)", keys, values);
}

PyDoc_STRVAR(scan_doc, "scan(token, first, skip, entries, comments, stray, long_lines, hint) -> (line, plain, header)\n\n"
                       "See ini._scan_python, which this does exactly; `hint` is unused here.");

static PyObject *scan(PyObject *Py_UNUSED(self), PyObject *args) {
    PyObject *token, *hint;
    Py_ssize_t first, skip;
    Body body = {NULL, NULL, NULL, 1};
    PyObject *long_lines;
    if (!PyArg_ParseTuple(args, "UnnO!O!O!O!O", &token, &first, &skip, &PyList_Type, &body.entries, &PyList_Type,
                          &body.comments, &PyList_Type, &body.stray, &PyList_Type, &long_lines, &hint))
        return NULL;
    if (!entry_type) {
        PyErr_SetString(PyExc_RuntimeError, "_scan.setup(Entry) was not called");
        return NULL;
    }
    Text t = {PyUnicode_KIND(token), PyUnicode_DATA(token), token};
    Py_ssize_t size = PyUnicode_GET_LENGTH(token), position = 0, index = 0;
    PyObject *header = NULL;
    for (;;) {
        Py_ssize_t start = position;
        Py_UCS4 c = 0;
        while (position < size && (c = AT(&t, position)) != '\r' && c != '\n')
            position++;
        Py_ssize_t end = position;
        int more = position < size;
        if (more)
            position += (c == '\r' && position + 1 < size && AT(&t, position + 1) == '\n') ? 2 : 1;
        Py_ssize_t line = first + index;
        if (end - start > MAX_LINE && append_pair(long_lines, line, PyLong_FromSsize_t(end - start)) < 0)
            goto failed;
        if (index < skip) {
            if (index == 0 && !(header = read_header(&t, start, end)))
                goto failed;
        } else if (body_line(&t, start, end, line, &body) < 0) {
            goto failed;
        }
        index++;
        if (!more)
            break;
    }
    if (!header)
        return Py_BuildValue("(nOO)", first + index - 1, Py_None, Py_None);
    PyObject *plain = plain_keys(body.entries, first, body.plain);
    if (!plain)
        goto failed;
    return Py_BuildValue("(nNN)", first + index - 1, plain, header);
failed:
    Py_XDECREF(header);
    return NULL;
}

static PyObject *setup(PyObject *Py_UNUSED(self), PyObject *type) {
    if (!PyType_Check(type) || !PyType_IsSubtype((PyTypeObject *)type, &PyTuple_Type)) {
        PyErr_SetString(PyExc_TypeError, "setup() takes the Entry tuple class");
        return NULL;
    }
    Py_INCREF(type);
    Py_XSETREF(entry_type, type);
    Py_RETURN_NONE;
}

static PyMethodDef methods[] = {
    {"scan", scan, METH_VARARGS, scan_doc},
    {"setup", setup, METH_O, "setup(Entry): the class of the entries scan() makes."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    .m_base = PyModuleDef_HEAD_INIT,
    .m_name = "_scan",
    .m_doc = "ini.py's per-line scanning, compiled.",
    .m_size = -1,
    .m_methods = methods,
};

PyMODINIT_FUNC PyInit__scan(void) { return PyModule_Create(&module); }
