// NewFileDialog: every built-in family is offered and every choice the dialog can make is a
// consistent one.
#include "dict/dictionary_loader.h"
#include "widgets/files/new_file_dialog.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QEvent>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <algorithm>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

const dev::DictionarySet &dictionaries()
{
    return *dev::builtinDictionaries();
}

template<typename T> T *child(const QObject &parent, const char *name)
{
    T *found = parent.findChild<T *>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
}

bool contains(const std::vector<std::string> &list, const std::string &value)
{
    return std::find(list.begin(), list.end(), value) != list.end();
}

std::vector<std::string> itemKeys(const QComboBox *box)
{
    std::vector<std::string> out;
    for (int i = 0; i < box->count(); ++i)
        out.push_back(box->itemData(i).toString().toStdString());
    return out;
}

TEST(NewFileDialog, ListsEveryFamilyOfTheBuiltInDictionaries)
{
    ui::NewFileDialog dialog(dictionaries());
    const auto *family = child<QComboBox>(dialog, "family");
    EXPECT_EQ(itemKeys(family), dictionaries().families());
    EXPECT_EQ(family->count(), 8); // 5 DMA-2, OPAT, ED1/SD1, SD7
    for (int i = 0; i < family->count(); ++i)
        EXPECT_FALSE(family->itemText(i).isEmpty()) << i;
}

TEST(NewFileDialog, EveryChoiceIsConsistent)
{
    ui::NewFileDialog dialog(dictionaries());
    auto *family = child<QComboBox>(dialog, "family");
    auto *version = child<QComboBox>(dialog, "version");
    auto *mode = child<QComboBox>(dialog, "mode");
    auto *ok = child<QDialogButtonBox>(dialog, "buttons")->button(QDialogButtonBox::Ok);
    for (int f = 0; f < family->count(); ++f) {
        family->setCurrentIndex(f);
        const dev::Dictionary *dict =
            dictionaries().find(family->itemData(f).toString().toStdString());
        ASSERT_NE(dict, nullptr);
        // The lists are the dictionary's own.
        std::vector<std::string> versions = itemKeys(version);
        std::sort(versions.begin(), versions.end());
        std::vector<std::string> expected = dict->versions;
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(versions, expected) << dict->family;
        EXPECT_EQ(itemKeys(mode), dict->modes) << dict->family;
        for (int v = 0; v < std::max(1, version->count()); ++v) {
            if (version->count() > 0)
                version->setCurrentIndex(v);
            for (int m = 0; m < mode->count(); ++m) {
                mode->setCurrentIndex(m);
                const model::NewFileChoice c = dialog.choice();
                EXPECT_EQ(c.dictionary, dict);
                EXPECT_TRUE(dict->versions.empty() ? c.version.empty()
                                                   : contains(dict->versions, c.version))
                    << dict->family << " " << c.version;
                EXPECT_TRUE(contains(dict->modes, c.mode)) << dict->family << " " << c.mode;
                EXPECT_EQ(c.modules, 1);
                EXPECT_TRUE(c.valid()) << dict->family << " V" << c.version << " mode " << c.mode;
                EXPECT_TRUE(ok->isEnabled());
                if (dict->protocol == dev::DeviceProtocol::Hcs) {
                    EXPECT_EQ(c.modeRaw, std::stoi(c.mode));
                }
            }
        }
    }
}

TEST(NewFileDialog, ModuleCountFollowsTheFamily)
{
    ui::NewFileDialog dialog(dictionaries());
    auto *modules = child<QSpinBox>(dialog, "modules");
    auto *version = child<QComboBox>(dialog, "version");

    ASSERT_TRUE(dialog.setFamily("opat"));
    EXPECT_EQ(modules->maximum(), 8);         // master + 7 CAN slaves
    EXPECT_EQ(dialog.choice().version, "34"); // newest first
    const int slave = version->findData(QStringLiteral("31"));
    ASSERT_GE(slave, 0);
    version->setCurrentIndex(slave);
    EXPECT_EQ(dialog.choice().version, "31");
    modules->setValue(3);
    // A node is led by the V34 master.
    EXPECT_EQ(dialog.choice().version, "34");
    EXPECT_FALSE(version->isEnabled());
    const auto places = model::modulePlaces(dialog.choice());
    ASSERT_EQ(places.size(), 3u);
    EXPECT_EQ(places[0].address, 0);
    EXPECT_EQ(places[0].version, "34");
    EXPECT_EQ(places[2].address, 2);
    EXPECT_EQ(places[2].version, "31");
    EXPECT_FALSE(child<QLabel>(dialog, "summary")->text().isEmpty());

    ASSERT_TRUE(dialog.setFamily("dma-pn-v51"));
    EXPECT_EQ(modules->value(), 1);
    EXPECT_EQ(modules->maximum(), 5);
    modules->setValue(5);
    EXPECT_EQ(model::modulePlaces(dialog.choice()).back().address, 5); // E22 = 1..5

    ASSERT_TRUE(dialog.setFamily("wandfluh-sd7"));
    EXPECT_FALSE(modules->isEnabled());
    EXPECT_FALSE(version->isEnabled());
    EXPECT_EQ(dialog.choice().modules, 1);
    EXPECT_EQ(dialog.choice().modeRaw, -1); // SD7 modes are names, not E00 numbers

    EXPECT_FALSE(dialog.setFamily("dma-pn-common")); // abstract: not a device
}

TEST(NewFileDialog, RetranslatesOnLanguageChange)
{
    ui::NewFileDialog dialog(dictionaries());
    dialog.setWindowTitle(QString());
    QEvent change(QEvent::LanguageChange);
    QCoreApplication::sendEvent(&dialog, &change);
    EXPECT_FALSE(dialog.windowTitle().isEmpty());
}

} // namespace
} // namespace vt::test
