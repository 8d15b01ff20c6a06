#ifndef ddcontact_material_state_json_h
#define ddcontact_material_state_json_h

#include <ddcontact/body/material_state_fields.h>
#include <ddcontact/io/json.h>

namespace ddcontact
{
  /** A body's material state in summary.json (per body, and per load step
   * under load_steps[].bodies): largest_<output> for every state output
   * but the flag "yielded", and plastic_zone_measure. */
  void
  add_material_state(const MaterialStateSummary &state, Json &body);
} // namespace ddcontact

#endif
