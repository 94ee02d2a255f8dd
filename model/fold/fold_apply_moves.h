// The order in which to change module addresses (DMA E22) on a live node so that no two modules
// ever answer to the same address: a module moves only onto a free address, and a ring of
// swaps (1→2, 2→1) is broken through a spare address. Plain functions; any thread.
#pragma once

#include <optional>
#include <vector>

namespace vt::model {

struct AddressMove
{
    int module = 0; // index into the list given to planAddressMoves
    int from = 0;
    int to = 0;

    bool operator==(const AddressMove &) const = default;
};

struct AddressChange
{
    int current = 0;
    int target = 0;
};

// Moves that take every module from `current` to `target`, one at a time, never onto an address
// another module holds at that moment. Spare addresses are taken from `lowest`..`highest`
// (DMA Profinet manual §1.5: E22 1..32), highest first. nullopt when the targets repeat or no
// spare address is left for a ring.
std::optional<std::vector<AddressMove>> planAddressMoves(const std::vector<AddressChange> &changes,
                                                         int lowest = 1, int highest = 32);

} // namespace vt::model
