// Every numeric input of the GUI in both languages, after start-up in either language and after a
// run-time switch (ARCHITECTURE.md, trust rules: numbers are parsed exactly in the UI language or
// refused): "1,5" is 1.5 only in German and "1.5" only in English; "1.500,25", "1,500.25", "1e3",
// "abc", "" and a value outside the range are refused with a sentence in the UI language that
// names the expected notation, and the value stays what it was — never 1.0, never 15.
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "dict/dictionary_loader.h"
#include "model/curve/lcurve_table_model.h"
#include "model/number_text.h"
#include "model/params/param_roles.h"
#include "model/params/parameter_tree_model.h"
#include "test_wait.h"
#include "widgets/connect/connect_dialog.h"
#include "widgets/curve/lcurve_delegate.h"
#include "widgets/editor/param_delegate.h"
#include "widgets/editor/parameter_editor.h"
#include "widgets/files/new_file_dialog.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/inspector/compose_panel.h"
#include "widgets/inspector/inspector_view.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/number_box.h"

#include <QAction>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStyleOptionViewItem>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

using dev::Language;

enum class Start { English, German, EnglishThenGerman, GermanThenEnglish };

Language startLanguage(Start s)
{
    return s == Start::German || s == Start::GermanThenEnglish ? Language::German
                                                               : Language::English;
}

Language finalLanguage(Start s)
{
    return s == Start::German || s == Start::EnglishThenGerman ? Language::German
                                                               : Language::English;
}

QString code(Language l)
{
    return l == Language::German ? QStringLiteral("de") : QStringLiteral("en");
}

std::string startName(const ::testing::TestParamInfo<Start> &info)
{
    switch (info.param) {
    case Start::English: return "StartedEnglish";
    case Start::German: return "StartedGerman";
    case Start::EnglishThenGerman: return "SwitchedToGerman";
    case Start::GermanThenEnglish: return "SwitchedToEnglish";
    }
    return "?";
}

// One of our spin boxes, decimal or whole, seen through one interface.
struct Input
{
    QString name;
    QAbstractSpinBox *box = nullptr;
    int decimals = 0;
    double min = 0, max = 0;
    std::function<std::optional<double>()> number;
    std::function<double()> value;
    std::function<void(double)> setValue;
    std::function<QString()> refusal;
    std::function<QString()> cleanText;
};

QString nameOf(const QWidget *w)
{
    QStringList path;
    for (const QObject *o = w; o; o = o->parent())
        path.prepend(QStringLiteral("%1(%2)").arg(QString::fromLatin1(o->metaObject()->className()),
                                                  o->objectName()));
    return path.join(QLatin1Char('/'));
}

std::vector<Input> inputsIn(const QWidget *root)
{
    std::vector<Input> inputs;
    for (ui::NumberBox *b : root->findChildren<ui::NumberBox *>())
        inputs.push_back({nameOf(b), b, b->decimals(), b->minimum(), b->maximum(),
                          [b] { return b->number(); }, [b] { return b->value(); },
                          [b](double v) { b->setValue(v); }, [b] { return b->refusal(); },
                          [b] { return b->cleanText(); }});
    for (ui::WholeNumberBox *b : root->findChildren<ui::WholeNumberBox *>())
        inputs.push_back({nameOf(b), b, 0, double(b->minimum()), double(b->maximum()),
                          [b]() -> std::optional<double> {
                              const auto n = b->number();
                              return n ? std::optional<double>(*n) : std::nullopt;
                          },
                          [b] { return double(b->value()); },
                          [b](double v) { b->setValue(static_cast<int>(v)); },
                          [b] { return b->refusal(); }, [b] { return b->cleanText(); }});
    return inputs;
}

// What a person types, then Enter.
void type(QAbstractSpinBox *box, const QString &text)
{
    auto *edit = box->findChild<QLineEdit *>();
    edit->selectAll();
    QTest::keyClick(box, Qt::Key_Backspace);
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
}

// The value a box holds before the entry: not 1.5, shown differently in the two languages where
// the box has decimals ("2,5" / "2.5").
double startValue(const Input &in)
{
    for (double v : {2.5, 2.0, 20.0})
        if (v >= in.min && v <= in.max && (in.decimals > 0 || v == std::floor(v)))
            return v;
    return in.max;
}

// The entries of the matrix, with the out-of-range one written in the box's own notation.
QStringList entries(const Input &in, Language lang)
{
    QStringList list{"1,5", "1.5", "1.500,25", "1,500.25", "1e3", "abc", ""};
    if (std::isfinite(in.max) && in.max < 1e9)
        list << model::formatNumber(in.max + 1, in.decimals, lang);
    return list;
}

// The refusal is in the UI language and says what to type instead (the notation, or the range).
void expectRefusalSentence(const QString &refusal, Language lang, const QString &where)
{
    EXPECT_FALSE(refusal.isEmpty()) << where.toStdString();
    const bool german =
        refusal.contains(QLatin1String("Zahl")) || refusal.contains(QLatin1String("Bereich"));
    const bool english =
        refusal.contains(QLatin1String("number")) || refusal.contains(QLatin1String("range"));
    if (lang == Language::German) {
        EXPECT_TRUE(german && !english) << where.toStdString() << ": " << refusal.toStdString();
    } else {
        EXPECT_TRUE(english && !german) << where.toStdString() << ": " << refusal.toStdString();
    }
}

void checkInput(Input &in, Language lang)
{
    const bool oneAndAHalfFits = in.decimals > 0 && 1.5 >= in.min && 1.5 <= in.max;
    const QString own = model::formatNumber(1.5, 1, lang); // "1,5" / "1.5"
    for (const QString &text : entries(in, lang)) {
        const QString where = QStringLiteral("%1 [%2] \"%3\"").arg(in.name, code(lang), text);
        const double before = startValue(in);
        in.setValue(before);
        QSignalSpy refused(in.box, SIGNAL(refused(QString)));
        type(in.box, text);
        if (text == own && oneAndAHalfFits) {
            EXPECT_EQ(in.value(), 1.5) << where.toStdString();
            if (in.box->isVisible()) { // a hidden spin box renders its text when shown
                EXPECT_TRUE(in.box->text().contains(model::formatNumber(1.5, in.decimals, lang)))
                    << where.toStdString() << ": " << in.box->text().toStdString();
            }
            EXPECT_EQ(refused.count(), 0) << where.toStdString();
            continue;
        }
        EXPECT_FALSE(in.number()) << where.toStdString();
        EXPECT_EQ(in.value(), before) << where.toStdString() << " became " << in.value();
        EXPECT_EQ(refused.count(), 1) << where.toStdString();
        const QString refusal = in.refusal();
        expectRefusalSentence(refusal, lang, where);
        if (refused.count() == 1) {
            EXPECT_EQ(refused.front().front().toString(), refusal) << where.toStdString();
        }
        // The typed text stays for correcting; it is not replaced by the previous value.
        EXPECT_TRUE(in.box->text().startsWith(text) || text.isEmpty())
            << where.toStdString() << ": " << in.box->text().toStdString();
    }
}

class NumberInput : public ::testing::TestWithParam<Start>
{
protected:
    void SetUp() override
    {
        settings = std::make_unique<app::AppSettings>(dir.filePath("settings.ini"));
        ASSERT_TRUE(language.setLanguage(code(startLanguage(GetParam()))));
        window = std::make_unique<app::MainWindow>(*settings, language);
        window->show();
        QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
        model::ConnectionSpec spec;
        spec.kind = model::ConnectionKind::Sim;
        spec.sim.family = "dma-pn-v51";
        window->device().connectTo(spec);
        ASSERT_TRUE(read.wait(kWaitMs));
        ui::FoldWizard *wizard = window->openFoldWizard();
        // The wizard reads the node before it shows its first page.
        ASSERT_TRUE(test::waitUntil([&] { return wizard->isVisible(); }, kWaitMs));
        connectDialog =
            new ui::ConnectDialog(window->workspace().dictionaries(), nullptr, window.get());
        connectDialog->setWindowFlag(Qt::Window);
        connectDialog->show();
        newFile = new ui::NewFileDialog(window->workspace().dictionaries(), window.get());
        newFile->setWindowFlag(Qt::Window);
        newFile->show();
        // The curve table's editor as its delegate makes it, on the OPAT's L block.
        curves.setDictionary(*dev::builtinDictionaries()->find("opat"), "", "");
        curves.setValues([](const dev::ParamMeta &row) -> std::optional<double> {
            return *row.defaultValue * 0.001;
        });
        curveHost = new QWidget(window.get());
        curveEditor = curveDelegate.createEditor(curveHost, QStyleOptionViewItem(),
                                                 curves.indexOf(0, 3, model::LAxis::Y));
        QCoreApplication::processEvents();

        // Values shown before the switch, to see them re-rendered after it.
        for (Input &in : inputsIn(window.get()))
            in.setValue(startValue(in));
        if (startLanguage(GetParam()) != finalLanguage(GetParam())) {
            window
                ->findChild<QAction *>(finalLanguage(GetParam()) == Language::German
                                           ? "actionGerman"
                                           : "actionEnglish")
                ->trigger();
            QCoreApplication::processEvents();
        }
        lang = finalLanguage(GetParam());
    }

    QTemporaryDir dir;
    app::Language language;
    std::unique_ptr<app::AppSettings> settings;
    std::unique_ptr<app::MainWindow> window;
    ui::ConnectDialog *connectDialog = nullptr;
    ui::NewFileDialog *newFile = nullptr;
    model::LCurveTableModel curves;
    ui::LCurveDelegate curveDelegate;
    QWidget *curveHost = nullptr;
    QWidget *curveEditor = nullptr;
    Language lang = Language::English;
};

TEST_P(NumberInput, EverySpinBoxParsesExactlyInTheUiLanguageOrRefuses)
{
    std::vector<Input> inputs = inputsIn(window.get());
    QStringList names;
    for (const Input &in : inputs)
        names << in.name;
    // The monitor's rate, window and step; the connect dialog's six; the new-file dialog's module
    // count; the fold wizard's pages (node address, SNUM, module count, bench interval); the
    // curve table's cell editor.
    for (const char *part : {"MonitorView", "StepControl", "SerialPage", "TcpPage", "CanPage",
                             "HartPage", "SimPage", "NewFileDialog", "FoldWizard"})
        EXPECT_TRUE(names.filter(QString::fromLatin1(part)).size() > 0)
            << "no numeric input found in " << part;
    EXPECT_GE(inputs.size(), 15u) << names.join(QLatin1Char('\n')).toStdString();
    ASSERT_NE(qobject_cast<ui::NumberBox *>(curveEditor), nullptr);
    // No stock spin box is left: each would read numbers in the locale it was made in. The PLC
    // bench's control word is hexadecimal, the same in both languages.
    for (const QAbstractSpinBox *box : window->findChildren<QAbstractSpinBox *>()) {
        const auto *spin = qobject_cast<const QSpinBox *>(box);
        const bool ours = qobject_cast<const ui::NumberBox *>(box) ||
                          qobject_cast<const ui::WholeNumberBox *>(box);
        EXPECT_TRUE(ours || (spin && spin->displayIntegerBase() == 16))
            << nameOf(box).toStdString();
    }

    int checked = 0;
    for (Input &in : inputs) {
        in.box->setEnabled(true); // e.g. an option's box, enabled by its check box
        if (!in.box->isEnabled())
            continue; // its page is not in use; it gets no keys
        // A value shown before a run-time switch is shown in the new notation now.
        const double shown = in.value();
        if (in.box->isVisible()) {
            EXPECT_EQ(in.cleanText(), in.box->specialValueText().isEmpty() || shown != in.min
                                          ? model::formatNumber(shown, in.decimals, lang)
                                          : in.box->specialValueText())
                << in.name.toStdString();
        }
        checkInput(in, lang);
        ++checked;
    }
    EXPECT_GE(checked, 14);
}

TEST_P(NumberInput, TheCurveCellTakesOnlyAnExactNumber)
{
    auto *box = qobject_cast<ui::NumberBox *>(curveEditor);
    ASSERT_NE(box, nullptr);
    const QModelIndex cell = curves.indexOf(0, 3, model::LAxis::Y);
    curveDelegate.setEditorData(box, cell);
    const double before = cell.data(Qt::EditRole).toDouble();
    QSignalSpy refused(&curveDelegate, &ui::LCurveDelegate::refused);
    QSignalSpy edited(&curves, &model::LCurveTableModel::rowsEdited);
    box->findChild<QLineEdit *>()->setText(lang == Language::German ? "1.5" : "1,5");
    curveDelegate.setModelData(box, &curves, cell);
    EXPECT_EQ(refused.count(), 1);
    EXPECT_EQ(edited.count(), 0);
    EXPECT_EQ(cell.data(Qt::EditRole).toDouble(), before);
    box->findChild<QLineEdit *>()->setText(model::formatNumber(1.5, box->decimals(), lang));
    curveDelegate.setModelData(box, &curves, cell);
    EXPECT_EQ(refused.count(), 1);
    EXPECT_EQ(cell.data(Qt::EditRole).toDouble(), 1.5);
}

// The editor's delegate hands the text to the tree model, which parses it through the same
// function: a row with decimals and a whole-number row.
TEST_P(NumberInput, EditorCellsParseExactlyInTheUiLanguageOrRefuse)
{
    model::ParameterTreeModel *tree = window->editor()->treeModel();
    const model::ParamModule &module = window->workspace().document().module(0);
    const dev::ParamMeta *decimal = nullptr;
    const dev::ParamMeta *whole = nullptr;
    for (const dev::ParamMeta &row : module.dictionary->params) {
        const QModelIndex index = tree->indexOf(0, &row, model::ParameterTreeModel::ColValue);
        if (!index.isValid() || !(index.flags() & Qt::ItemIsEditable) || !row.enums.empty() ||
            !row.bits.empty() || row.isString() || index.data(model::ReadOnlyRole).toBool())
            continue;
        const double min = index.data(model::DisplayMinRole).toDouble();
        const double max = index.data(model::DisplayMaxRole).toDouble();
        const int decimals = index.data(model::DecimalsRole).toInt();
        if (!decimal && decimals >= 1 && min <= 1.5 && max >= 1.5 && max < 1e6)
            decimal = &row;
        if (!whole && decimals == 0 && row.scale.name.empty() && min <= 15 && max >= 15 &&
            max < 1e6)
            whole = &row;
    }
    ASSERT_NE(decimal, nullptr);
    ASSERT_NE(whole, nullptr);
    ui::ParamDelegate delegate;
    QWidget host;
    for (const dev::ParamMeta *row : {decimal, whole}) {
        const QModelIndex index = tree->indexOf(0, row, model::ParameterTreeModel::ColValue);
        const int decimals = index.data(model::DecimalsRole).toInt();
        const double max = index.data(model::DisplayMaxRole).toDouble();
        const QString own = model::formatNumber(1.5, 1, lang);
        QStringList list{"1,5", "1.5", "1.500,25", "1,500.25",
                         "1e3", "abc", "",         model::formatNumber(max + 1, decimals, lang)};
        for (const QString &text : list) {
            const QString where = QStringLiteral("%1 [%2] \"%3\"")
                                      .arg(QString::fromStdString(row->name), code(lang), text);
            const QVariant before = index.data(model::RawValueRole);
            QSignalSpy refused(tree, &model::ParameterTreeModel::editRefused);
            QWidget *editor = delegate.createEditor(&host, QStyleOptionViewItem(), index);
            ASSERT_NE(editor, nullptr);
            delegate.setEditorData(editor, index);
            qobject_cast<QLineEdit *>(editor)->setText(text);
            delegate.setModelData(editor, tree, index);
            delete editor;
            if (text == own && row == decimal) {
                EXPECT_EQ(refused.count(), 0) << where.toStdString();
                EXPECT_EQ(index.data(Qt::EditRole).toString(),
                          model::formatNumber(1.5, decimals, lang))
                    << where.toStdString();
                continue;
            }
            EXPECT_EQ(refused.count(), 1) << where.toStdString();
            EXPECT_EQ(index.data(model::RawValueRole), before) << where.toStdString();
            if (refused.count() == 1)
                expectRefusalSentence(refused.front().at(1).toString(), lang, where);
        }
    }
}

// The inspector's compose fields are whole numbers (or 0x… hex) in the UI language's notation.
TEST_P(NumberInput, ComposeFieldsTakeWholeNumbersInTheUiLanguage)
{
    auto *panel = window->inspector()->findChild<ui::ComposePanel *>();
    ASSERT_NE(panel, nullptr);
    panel->setKind(dev::inspect::ComposeKind::GatewayWrite);
    panel->setFieldText("value", "15");
    EXPECT_TRUE(panel->problem().isEmpty()) << panel->problem().toStdString();
    for (const char *text : {"1,5", "1.5", "1.500,25", "1,500.25", "1e3", "abc", "", "99999"}) {
        panel->setFieldText("value", QString::fromUtf8(text));
        const QString where = QStringLiteral("value [%1] \"%2\"").arg(code(lang), text);
        EXPECT_FALSE(panel->problem().isEmpty()) << where.toStdString();
        EXPECT_FALSE(panel->composed().has_value()) << where.toStdString();
    }
    panel->setFieldText("value", "1,5");
    expectRefusalSentence(panel->problem(), lang, "value 1,5");
}

INSTANTIATE_TEST_SUITE_P(Languages, NumberInput,
                         ::testing::Values(Start::English, Start::German, Start::EnglishThenGerman,
                                           Start::GermanThenEnglish),
                         startName);

} // namespace
} // namespace vt::test
