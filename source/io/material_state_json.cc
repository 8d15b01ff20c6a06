#include <ddcontact/io/material_state_json.h>

namespace ddcontact
{
  void
  add_material_state(const MaterialStateSummary &state, Json &body)
  {
    for (unsigned int k = 0; k < state.names.size(); ++k)
      if (state.names[k] != "yielded")
        body["largest_" + state.names[k]] = state.largest[k];
    body["plastic_zone_measure"] = state.yielded_measure;
  }
} // namespace ddcontact
