// CurveBinding: document values reach the curve model, a curve edit
// is one undoable document edit, and undo puts the curve back.
#include "dict/dictionary_loader.h"
#include "model/curve/lcurve_table_model.h"
#include "model/params/curve_binding.h"
#include "model/params/parameter_document.h"

#include <gtest/gtest.h>

namespace vt::test {
namespace {

TEST(CurveBinding, CurveEditsAreUndoableDocumentEdits)
{
    const dev::Dictionary &dma = *dev::builtinDictionaries()->find("dma-pn-v51");
    model::ParameterDocument doc;
    doc.createNew({&dma, "51", "3", 3, 1}, *dev::builtinDictionaries());
    model::LCurveTableModel curves;
    model::CurveBinding binding(doc, curves);
    binding.setModule(0);
    ASSERT_EQ(curves.curves().size(), 2u); // branch 1 and 2

    const dev::ParamMeta *y3 = dma.find("L1.y3");
    doc.editMany({{0, y3, dev::RawValue{2500.0}}}, [] { return QStringLiteral("set"); });
    EXPECT_EQ(curves.value(0, 3, model::LAxis::Y), std::optional<double>(2.5));

    EXPECT_FALSE(curves.editPoint(0, 3, std::nullopt, 3.0));
    EXPECT_EQ(doc.value(0, y3), dev::RawValue{3000.0});
    doc.undoStack()->undo();
    EXPECT_EQ(doc.value(0, y3), dev::RawValue{2500.0});
    EXPECT_EQ(curves.value(0, 3, model::LAxis::Y), std::optional<double>(2.5));
}

} // namespace
} // namespace vt::test
