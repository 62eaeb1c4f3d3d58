#include <gtest/gtest.h>

#include "EscapeKey.h"

namespace {

using namespace lit::editor;

// Escape pressed to close a menu closes the menu and keeps the selection; only with nothing
// open does it clear the selection.
TEST(EscapeKey, ClosesAnOpenMenuBeforeClearingTheSelection) {
    EXPECT_EQ(escapeAction(/*popupOpen=*/true), EscapeAction::ClosePopups);
    EXPECT_EQ(escapeAction(/*popupOpen=*/false), EscapeAction::ClearSelection);
}

}  // namespace
