// Bindings of the sim calls (bind_common.hpp).
#include "bind_common.hpp"

namespace evade::python {

void bind_sim(nb::module_&) {}

}  // namespace evade::python
