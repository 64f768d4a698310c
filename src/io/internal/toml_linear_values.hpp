// SPDX-License-Identifier: MIT
#pragma once
// Makes toml11 3.x parse in time linear in the file size. Include it (after <toml.hpp>) in every
// translation unit that calls toml::parse, before the call.
//
// Why: toml11 3.x's parse_value_helper asks the region of every parsed value for its comments,
// and region::comments() scans the value's whole line backwards to its start and forwards to its
// end, even with toml::discard_comments (toml::value's default, ours), which then drops them. A
// line of n values therefore costs n x (line length): one 300 kB line of 30 000 floats took 4 s,
// a 1 MiB line of integers minutes (issue 32, item 4). These explicit specializations, for
// toml::value and every value type the parser produces, build the same value without the
// comments it would discard, which is the only thing they change. toml11 4 has another parser,
// so they apply to 3.x only.

#include <string>
#include <toml.hpp>
#include <utility>

#if TOML11_VERSION_MAJOR == 3

static_assert(std::is_same_v<toml::value::comment_type, toml::discard_comments>,
              "toml_linear_values.hpp drops comments: only valid for toml::discard_comments");

// Each specialization is the body of toml11 3.7's parse_value_helper minus the comments().
#define CATENA_TOML_LINEAR_VALUE(T)                                                               \
  template <>                                                                                     \
  inline toml::result<toml::value, std::string> toml::detail::parse_value_helper<toml::value, T>( \
      toml::result<std::pair<T, toml::detail::region>, std::string> parsed) {                     \
    if (parsed.is_ok()) return toml::ok(toml::value(std::move(parsed.as_ok()), {}));              \
    return toml::err(std::move(parsed.as_err()));                                                 \
  }

CATENA_TOML_LINEAR_VALUE(toml::boolean)
CATENA_TOML_LINEAR_VALUE(toml::integer)
CATENA_TOML_LINEAR_VALUE(toml::floating)
CATENA_TOML_LINEAR_VALUE(toml::string)
CATENA_TOML_LINEAR_VALUE(toml::offset_datetime)
CATENA_TOML_LINEAR_VALUE(toml::local_datetime)
CATENA_TOML_LINEAR_VALUE(toml::local_date)
CATENA_TOML_LINEAR_VALUE(toml::local_time)
CATENA_TOML_LINEAR_VALUE(toml::value::array_type)
CATENA_TOML_LINEAR_VALUE(toml::value::table_type)

#undef CATENA_TOML_LINEAR_VALUE

#endif
