#include "model/fold/fold_apply_moves.h"

#include <algorithm>
#include <set>

namespace vt::model {

std::optional<std::vector<AddressMove>> planAddressMoves(const std::vector<AddressChange> &changes,
                                                         int lowest, int highest)
{
    std::set<int> targets;
    for (const AddressChange &c : changes)
        if (!targets.insert(c.target).second)
            return std::nullopt;

    std::vector<int> at; // where each module answers now
    for (const AddressChange &c : changes)
        at.push_back(c.current);
    const auto occupied = [&](int address, std::size_t except) {
        for (std::size_t i = 0; i < at.size(); ++i)
            if (i != except && at[i] == address)
                return true;
        return false;
    };

    std::vector<AddressMove> moves;
    for (;;) {
        bool moved = false;
        bool pending = false;
        for (std::size_t i = 0; i < changes.size(); ++i) {
            if (at[i] == changes[i].target)
                continue;
            pending = true;
            if (!occupied(changes[i].target, i)) {
                moves.push_back({static_cast<int>(i), at[i], changes[i].target});
                at[i] = changes[i].target;
                moved = true;
            }
        }
        if (!pending)
            return moves;
        if (moved)
            continue;
        // Every pending module waits for another: a ring. Park the first one on a spare address
        // that is neither held nor anyone's target.
        int spare = -1;
        for (int a = highest; a >= lowest; --a) {
            if (!targets.count(a) && std::find(at.begin(), at.end(), a) == at.end()) {
                spare = a;
                break;
            }
        }
        if (spare < 0)
            return std::nullopt;
        for (std::size_t i = 0; i < changes.size(); ++i) {
            if (at[i] != changes[i].target) {
                moves.push_back({static_cast<int>(i), at[i], spare});
                at[i] = spare;
                break;
            }
        }
    }
}

} // namespace vt::model
