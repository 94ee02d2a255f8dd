// ParameterDocument: the three value layers, undoable edits refused out of range
// with the limits named, the rows a safe write sends, and files that keep what they do not map.
#include "dict/dictionary_loader.h"
#include "files/param_file.h"
#include "model/params/parameter_document.h"

#include <gtest/gtest.h>

namespace vt::test {
namespace {

using model::Layer;
using model::ParameterDocument;

const dev::DictionarySet &dictionaries()
{
    return *dev::builtinDictionaries();
}
const dev::Dictionary &dma()
{
    return *dictionaries().find("dma-pn-v51");
}
const dev::ParamMeta *row(const char *name)
{
    return dma().find(name);
}

TEST(ParameterDocument, NewFileHoldsTheDictionaryDefaults)
{
    ParameterDocument doc;
    doc.createNew({&dma(), "51", "3", 3, 2}, dictionaries());
    ASSERT_EQ(doc.moduleCount(), 2);
    EXPECT_EQ(doc.module(1).address, 2);
    const auto c107 = doc.value(0, row("C1.07"));
    ASSERT_TRUE(c107);
    EXPECT_EQ(*c107, dev::RawValue{*row("C1.07")->defaultValue});
    EXPECT_FALSE(doc.isModified());
    EXPECT_FALSE(doc.hasFile());
}

TEST(ParameterDocument, EditIsUndoableAndRefusedOutOfRangeWithTheLimits)
{
    ParameterDocument doc;
    doc.createNew({&dma(), "51", "3", 3, 1}, dictionaries());
    EXPECT_FALSE(doc.edit(0, row("C1.07"), 1000.0));
    EXPECT_EQ(doc.value(0, row("C1.07")), dev::RawValue{1000.0});
    EXPECT_TRUE(doc.isModified());
    EXPECT_TRUE(doc.changed(0, row("C1.07")));

    const auto refused = doc.edit(0, row("C1.07"), 1e7);
    ASSERT_TRUE(refused);
    EXPECT_TRUE(refused->contains("9.999")) << refused->toStdString(); // the upper limit in volts
    doc.setLanguage(dev::Language::German);
    const auto refusedDe = doc.edit(0, row("C1.07"), 1e7);
    ASSERT_TRUE(refusedDe);
    EXPECT_TRUE(refusedDe->contains("9,999")) << refusedDe->toStdString();
    doc.setLanguage(dev::Language::English);
    EXPECT_EQ(doc.value(0, row("C1.07")), dev::RawValue{1000.0});

    EXPECT_TRUE(doc.edit(0, row("d1.11"), 5.0)); // read only
    doc.undoStack()->undo();
    EXPECT_EQ(doc.value(0, row("C1.07")), dev::RawValue{*row("C1.07")->defaultValue});
    EXPECT_FALSE(doc.isModified());
    doc.undoStack()->redo();
    EXPECT_EQ(doc.value(0, row("C1.07")), dev::RawValue{1000.0});
}

TEST(ParameterDocument, ReadValuesFollowUnlessTheUserOrAFileSetThem)
{
    model::DeviceImage image;
    image.beginConnection();
    ParameterDocument doc;
    doc.setDeviceImage(&image);
    model::ModuleInfo info;
    info.address = 1;
    info.dictionary = &dma();
    info.identification.family = "dma-pn-v51";
    info.identification.version = "51.02";
    info.identification.mode = "3";
    doc.attachDevice({info});
    ASSERT_EQ(doc.moduleCount(), 1);
    EXPECT_TRUE(doc.module(0).online);

    image.recordRead(1, {{row("C1.07"), 500.0}, {row("C1.08"), 600.0}, {row("d1.11"), 42.0}});
    EXPECT_EQ(doc.value(0, row("C1.07")), dev::RawValue{500.0});
    EXPECT_FALSE(doc.differsFromDevice(0, row("C1.07")));
    EXPECT_TRUE(doc.pendingWrites(0).empty());

    EXPECT_FALSE(doc.edit(0, row("C1.07"), 1000.0));
    // A later read (the live d-block) does not overwrite the edit, but updates display values.
    image.recordRead(1, {{row("C1.07"), 500.0}, {row("d1.11"), 43.0}});
    EXPECT_EQ(doc.value(0, row("C1.07")), dev::RawValue{1000.0});
    EXPECT_EQ(doc.value(0, row("d1.11")), dev::RawValue{43.0});
    EXPECT_TRUE(doc.differsFromDevice(0, row("C1.07")));

    const auto pending = doc.pendingWrites(0);
    ASSERT_EQ(pending.size(), 1u);
    EXPECT_EQ(pending[0].row, row("C1.07"));
    EXPECT_EQ(pending[0].value, dev::RawValue{1000.0});
    EXPECT_EQ(pending[0].before, dev::RawValue{500.0});

    // Written and acknowledged: the Device column follows; undo then differs from the device again.
    image.recordWritten(1, row("C1.07"), 1000.0);
    EXPECT_FALSE(doc.differsFromDevice(0, row("C1.07")));
    doc.undoStack()->undo();
    EXPECT_EQ(doc.value(0, row("C1.07")), dev::RawValue{500.0});
    EXPECT_TRUE(doc.differsFromDevice(0, row("C1.07")));

    doc.revertToDevice();
    EXPECT_FALSE(doc.differsFromDevice(0, row("C1.07")));
}

TEST(ParameterDocument, SaveKeepsWhatThisVersionDoesNotApply)
{
    dev::files::ParamFile file;
    dev::files::ModuleRecord record;
    record.address = 3;
    record.family = "dma-pn-v51";
    record.version = "51.02";
    record.mode = "3";
    record.label = "Press 1";
    record.values.push_back(dev::files::makeValueRow(*row("C1.07"), 800.0));
    dev::files::ValueRow unknown;
    unknown.name = "Z9.99";
    unknown.raw = 7.0;
    unknown.extra["comment"] = "from a newer version";
    record.values.push_back(unknown);
    record.extra["site"] = "hall 2";
    file.modules.push_back(record);
    dev::files::ModuleRecord foreign;
    foreign.address = 9;
    foreign.family = "no-such-family";
    foreign.values.push_back(unknown);
    file.modules.push_back(foreign);
    file.extra["project"] = "P-17";

    ParameterDocument doc;
    doc.loadFile(file, dictionaries(), QStringLiteral("/tmp/x.vtpar"));
    ASSERT_EQ(doc.moduleCount(), 1);
    ASSERT_TRUE(doc.module(0).mapReport);
    EXPECT_EQ(doc.module(0).mapReport->count(dev::files::MapStatus::Unknown), 1u);
    EXPECT_EQ(doc.unknownFamilies().size(), 1u);
    EXPECT_EQ(doc.value(0, row("C1.07"), Layer::File), dev::RawValue{800.0});

    EXPECT_FALSE(doc.edit(0, row("C1.07"), 900.0));
    const dev::files::ParamFile saved = doc.toParamFile("ValveTune test");
    EXPECT_EQ(saved.extra.value("project", ""), "P-17");
    ASSERT_EQ(saved.modules.size(), 2u);
    const dev::files::ModuleRecord &out = saved.modules[0];
    EXPECT_EQ(out.label, "Press 1");
    EXPECT_EQ(out.extra.value("site", ""), "hall 2");
    ASSERT_TRUE(out.find("C1.07"));
    EXPECT_EQ(out.find("C1.07")->raw, dev::RawValue{900.0});
    ASSERT_TRUE(out.find("Z9.99"));
    EXPECT_EQ(out.find("Z9.99")->extra.value("comment", ""), "from a newer version");
    EXPECT_EQ(saved.modules[1].family, "no-such-family");

    doc.markSaved(QStringLiteral("/tmp/y.vtpar"));
    EXPECT_FALSE(doc.isModified());
    EXPECT_EQ(doc.value(0, row("C1.07"), Layer::File), dev::RawValue{900.0});
    EXPECT_FALSE(doc.changed(0, row("C1.07")));
}

} // namespace
} // namespace vt::test
