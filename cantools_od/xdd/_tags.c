/* The XML reader's per-element byte work (xdd/safe.py's `tag_end`, xdd/locations.py's `attribute_spans` and
 * `Positions.at`), compiled. Reading a large XDD calls each of them about once per element or attribute; as
 * Python they took about a quarter of the read.
 *
 * Each does exactly what its Python form does, which stays as the reference: the tests compare the two on every
 * real XML file and on generated tags. Expat has checked the document before any of them runs, but none of
 * them relies on that: any bytes give the Python form's answer.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

/* bytes regular expressions' \s */
#define SPACE(c) ((c) == ' ' || (c) == '\t' || (c) == '\n' || (c) == '\r' || (c) == '\f' || (c) == '\v')
#define QUOTE(c) ((c) == '"' || (c) == '\'')
#define NAME_CHAR(c) (!SPACE(c) && (c) != '=' && (c) != '/' && (c) != '>' && !QUOTE(c))

static Py_ssize_t clamp(Py_ssize_t offset, Py_ssize_t size) {
    /* a bound as a compiled pattern's pos and endpos take it: from 0 to the size */
    return offset < 0 ? 0 : offset > size ? size : offset;
}

PyDoc_STRVAR(tag_end_doc, "tag_end(data, start) -> int\n\nSee safe.tag_end, which this does exactly.");

static PyObject *tag_end(PyObject *Py_UNUSED(self), PyObject *args) {
    Py_buffer view;
    Py_ssize_t start;
    if (!PyArg_ParseTuple(args, "y*n", &view, &start))
        return NULL;
    const char *data = view.buf;
    Py_ssize_t size = view.len, found = size;
    Py_ssize_t at = clamp(start, size);
    if (at < size && data[at] == '<') {
        for (Py_ssize_t i = at + 1; i < size; i++) {
            char c = data[i];
            if (c == '>') {
                found = i + 1;
                break;
            }
            if (QUOTE(c)) {
                const char *close = memchr(data + i + 1, c, (size_t)(size - i - 1));
                if (!close)
                    break;
                i = close - data;
            }
        }
    }
    PyBuffer_Release(&view);
    return PyLong_FromSsize_t(found);
}

/* One attribute `name = "value"` matched at `i` (the Python form's _ATTRIBUTE); 0 when none is. */
static int attribute_at(const char *data, Py_ssize_t i, Py_ssize_t end, Py_ssize_t *name_end, Py_ssize_t *value,
                        Py_ssize_t *value_end) {
    Py_ssize_t j = i;
    while (j < end && NAME_CHAR(data[j]))
        j++;
    if (j == i)
        return 0;
    *name_end = j;
    while (j < end && SPACE(data[j]))
        j++;
    if (j >= end || data[j] != '=')
        return 0;
    j++;
    while (j < end && SPACE(data[j]))
        j++;
    if (j >= end || !QUOTE(data[j]))
        return 0;
    const char *close = memchr(data + j + 1, data[j], (size_t)(end - j - 1));
    if (!close)
        return 0;
    *value = j + 1;
    *value_end = close - data;
    return 1;
}

static int add_span(PyObject *spans, const char *data, Py_ssize_t i, Py_ssize_t name_end, Py_ssize_t value,
                    Py_ssize_t value_end) {
    PyObject *name = PyUnicode_DecodeUTF8(data + i, name_end - i, "replace");
    PyObject *span = name ? Py_BuildValue("(nnn)", i, value, value_end) : NULL;
    int failed = span ? PyDict_SetItem(spans, name, span) : -1;
    Py_XDECREF(name);
    Py_XDECREF(span);
    return failed;
}

PyDoc_STRVAR(spans_doc, "attribute_spans(data, start, end) -> dict\n\n"
                        "Attribute name -> (name offset, value start, value end) in the start tag data[start:end]; "
                        "see locations.attribute_spans, which this does exactly.");

static PyObject *attribute_spans(PyObject *Py_UNUSED(self), PyObject *args) {
    Py_buffer view;
    Py_ssize_t start, end;
    if (!PyArg_ParseTuple(args, "y*nn", &view, &start, &end))
        return NULL;
    const char *data = view.buf;
    start = clamp(start, view.len);
    end = clamp(end, view.len);
    PyObject *spans = PyDict_New();
    Py_ssize_t i = start;
    if (i < end && data[i] == '<' && i + 1 < end && !SPACE(data[i + 1]) && data[i + 1] != '/' && data[i + 1] != '>') {
        i++; /* the element's name, as _TAG_NAME reads it */
        while (i < end && !SPACE(data[i]) && data[i] != '/' && data[i] != '>')
            i++;
    }
    while (spans && i < end) {
        Py_ssize_t name_end, value, value_end;
        if (!attribute_at(data, i, end, &name_end, &value, &value_end)) {
            i++; /* as finditer: the next match may start one byte on */
            continue;
        }
        if (add_span(spans, data, i, name_end, value, value_end) < 0)
            Py_CLEAR(spans);
        i = value_end + 1;
    }
    PyBuffer_Release(&view);
    return spans;
}

PyDoc_STRVAR(position_doc, "position(starts, data, offset) -> (line, column)\n\n"
                           "See locations._position_python, which this does exactly.");

static PyObject *position(PyObject *Py_UNUSED(self), PyObject *args) {
    PyObject *starts;
    Py_buffer view;
    Py_ssize_t offset;
    if (!PyArg_ParseTuple(args, "O!y*n", &PyList_Type, &starts, &view, &offset))
        return NULL;
    PyObject *result = NULL;
    Py_ssize_t low = 0, high = PyList_GET_SIZE(starts);
    if (high == 0) {
        PyErr_SetString(PyExc_ValueError, "position() takes a non-empty list of line starts");
        goto done;
    }
    offset = offset < 0 ? 0 : offset; /* expat's "no position" */
    while (low < high) { /* bisect_right */
        Py_ssize_t middle = low + (high - low) / 2;
        Py_ssize_t value = PyLong_AsSsize_t(PyList_GET_ITEM(starts, middle));
        if (value == -1 && PyErr_Occurred())
            goto done;
        if (offset < value)
            high = middle;
        else
            low = middle + 1;
    }
    Py_ssize_t line = low;
    Py_ssize_t first = PyLong_AsSsize_t(PyList_GET_ITEM(starts, line ? line - 1 : PyList_GET_SIZE(starts) - 1));
    if (first == -1 && PyErr_Occurred())
        goto done;
    first = clamp(first, view.len);
    Py_ssize_t last = clamp(offset, view.len), column = 0, ascii = 1;
    const unsigned char *data = view.buf;
    for (Py_ssize_t i = first; i < last; i++)
        ascii &= data[i] < 0x80;
    if (ascii) {
        column = last > first ? last - first : 0;
    } else {
        PyObject *text = PyUnicode_DecodeUTF8((const char *)data + first, last - first, "replace");
        if (!text)
            goto done;
        column = PyUnicode_GET_LENGTH(text);
        Py_DECREF(text);
    }
    result = Py_BuildValue("(nn)", line, column + 1);
done:
    PyBuffer_Release(&view);
    return result;
}

static PyMethodDef methods[] = {
    {"tag_end", tag_end, METH_VARARGS, tag_end_doc},
    {"attribute_spans", attribute_spans, METH_VARARGS, spans_doc},
    {"position", position, METH_VARARGS, position_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    .m_base = PyModuleDef_HEAD_INIT,
    .m_name = "_tags",
    .m_doc = "The XML reader's per-element byte work, compiled.",
    .m_size = -1,
    .m_methods = methods,
};

PyMODINIT_FUNC PyInit__tags(void) { return PyModule_Create(&module); }
