// SPDX-License-Identifier: MIT
// Catena's exceptions as Python exceptions (docs/reference/python.md, "Errors"): bad input is a
// ValueError subclass whose message names the field, as in the CLI.
#include <cstring>
#include <filesystem>

#include "bindings.hpp"
#include "catena/core/error.hpp"

namespace catena::python {
namespace {

// Sets the Python exception `type` with `what` as its message. A message may quote bytes of a file
// in another encoding; pybind11's own call would decode it strictly and raise UnicodeDecodeError in
// place of the real error, so invalid bytes are written as \\xNN (Python's "backslashreplace").
void set_error(PyObject* type, const char* what) {
  PyObject* text =
      PyUnicode_DecodeUTF8(what, static_cast<Py_ssize_t>(std::strlen(what)), "backslashreplace");
  if (text == nullptr) return;  // the decoding error is already set
  PyErr_SetObject(type, text);
  Py_DECREF(text);
}

}  // namespace

void bind_errors(py::module_& module) {
  // Both are bad input, so ParseError (an unreadable or malformed scene) derives from InvalidInput
  // in Python and `except catena.InvalidInput` (or ValueError) catches every bad input.
  // Deliberately leaked: these must outlive every exception translation, and a static Python object
  // would be released after the interpreter has finalized.
  static auto& invalid_input =
      *new py::exception<InvalidInput>(module, "InvalidInput", PyExc_ValueError);
  static auto& parse_error =
      *new py::exception<ParseError>(module, "ParseError", invalid_input.ptr());
  invalid_input.attr("__doc__") =
      "Bad input (catena::InvalidInput): a value violates a documented constraint. A ValueError; "
      "the "
      "message names the field, its value and the constraint.";
  parse_error.attr("__doc__") =
      "A scene that cannot be read or parsed (catena::ParseError): unknown key, wrong type, bad "
      "TOML, "
      "unreadable file. A subclass of InvalidInput; the message names the file or '<dict>', the "
      "table "
      "and the key.";
  // Translators are tried in reverse order of registration: the most general one goes first.
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const std::filesystem::filesystem_error& error) {
      set_error(PyExc_OSError, error.what());
    } catch (const ParseError& error) {
      set_error(parse_error.ptr(), error.what());
    } catch (const Error& error) {
      set_error(invalid_input.ptr(), error.what());
    }
  });
}

}  // namespace catena::python
