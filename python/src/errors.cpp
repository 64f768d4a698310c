// SPDX-License-Identifier: MIT
// Catena's exceptions as Python exceptions (docs/reference/python.md, "Errors"): bad input is a
// ValueError subclass whose message names the field, as in the CLI.
#include <filesystem>

#include "bindings.hpp"
#include "catena/core/error.hpp"

namespace catena::python {

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
      PyErr_SetString(PyExc_OSError, error.what());
    } catch (const ParseError& error) {
      parse_error(error.what());
    } catch (const Error& error) {
      invalid_input(error.what());
    }
  });
}

}  // namespace catena::python
