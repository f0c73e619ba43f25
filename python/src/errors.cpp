// fastshade.InputError (a ValueError) carries the library's one-line InputError message.
#include "bindings.h"

#include "fastshade/error.h"

namespace fastshade::python {

void bind_errors(nanobind::module_& m) {
  nanobind::exception<InputError>(m, "InputError", PyExc_ValueError);
}

}  // namespace fastshade::python
