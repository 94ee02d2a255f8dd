// What the technician does at the node for a fold plan: which module
// gets which address and how (DMA: E22 left to right; OPAT: the master is SADR 0, the slaves by
// rotary switch), the E24 "126 = set by the master" rule with its power-cycle note, and the
// cable instruction of a point-to-point apply. Sentences through tr(), in the language shown when
// called (a page asks again on a language change); any thread.
#pragma once

#include "model/fold/fold_plan.h"

#include <QString>
#include <cstddef>
#include <vector>

namespace vt::model {

// Where the module sits and how its address is set, one sentence, e.g. "Module 2 (second from
// the left): E22 = 2." / "Module 3 (CAN slave): set the rotary switch to 2."
QString moduleAddressGuide(const FoldPlan &plan, std::size_t index);

// The node-wide rule for addresses (OPAT manual §1.4; DMA Profinet manual §2.2 / §4.1, DMA
// Profibus Anleitung §1.5): a paragraph for the address page.
QString nodeAddressRule(FoldNode node);

// OPAT manual §1.4: what the chosen E24 means, including the power-down/power-up note;
// empty when the master's E24 is left as it is.
QString profibusAddressNote(const FoldPlan &plan);

// Point-to-point apply: "Connect the service cable to module 2 (E22 will become 2), then press
// Next." (OPAT: which module by SADR / switch).
QString cableGuide(const FoldPlan &plan, std::size_t index);

} // namespace vt::model
