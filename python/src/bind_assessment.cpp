// Bindings of the assessment calls (bind_common.hpp).
#include "bind_common.hpp"

namespace evade::python {

void bind_assessment(nb::module_&) {}

}  // namespace evade::python
