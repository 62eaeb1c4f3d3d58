#pragma once
// A pass's screen-sized render targets for the size in use, plus those of the size used before it.
//
// Why the second set: the editor's interactive render scale switches between two sizes (full
// size when still, a smaller one while the camera moves or a value is dragged). Keeping the
// previous size's targets lets the switch back reuse them instead of reallocating: allocating the
// 1280×720 targets cost 120–590 ms on llvmpipe in the frame after a motion (docs/PERFORMANCE.md).
// The spare set stays empty until a second size is used (lit-render and the tests use one size).
// A third size replaces the *smaller* of the two sets: while the camera moves the interactive scale
// changes size now and then (128×72, 192×108, 256×144, ... within one motion), and dropping the
// least recently used set would drop the full size, so the still frame after every such motion
// would reallocate its targets (and lose the indirect history) after all (docs/PERFORMANCE.md,
// "Editor").
//
// `Targets` is a pass's plain struct of GL objects with `int width, height` members; it is swapped
// whole, so a target added to the struct cannot be forgotten by the swap.

#include <utility>

namespace lit {

template <class Targets>
class TargetsBySize {
public:
    enum class Selected {
        Unchanged,  // the targets in use already had this size
        Reused,     // the spare set had this size and is now in use
        Empty,      // neither had it: the set in use is empty, sized, and must be allocated
    };

    // Makes the targets of `width` × `height` the ones in use. The set that was in use becomes the
    // spare, except when neither set has this size: then the larger of the two stays as the spare
    // and the smaller one is replaced.
    Selected select(int width, int height) {
        if (current_.width == width && current_.height == height) return Selected::Unchanged;
        std::swap(current_, spare_);
        if (current_.width == width && current_.height == height) return Selected::Reused;
        if (area(current_) > area(spare_)) std::swap(current_, spare_);
        current_ = Targets{};  // frees the smaller set's GL objects before the new ones are made
        current_.width = width;
        current_.height = height;
        return Selected::Empty;
    }

    Targets& current() { return current_; }
    Targets* operator->() { return &current_; }
    const Targets* operator->() const { return &current_; }

private:
    static long long area(const Targets& t) { return static_cast<long long>(t.width) * t.height; }

    Targets current_, spare_;
};

}  // namespace lit
