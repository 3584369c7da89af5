// Bindings of the planners calls (bind_common.hpp).
#include "bind_common.hpp"

namespace evade::python {

void bind_planners(nb::module_&) {}

}  // namespace evade::python
