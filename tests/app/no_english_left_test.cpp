// German everywhere, also in texts built at run time: with every window open and the texts that
// only exist after something happened on them (connected to a 3-module node, a value edited, a
// set-value step written and verified, a composed frame answered, the fold wizard on its Apply
// page), one switch to German leaves no visible text that equals an English source of the
// catalogue (translations/valvetune_de.ts) whose German differs — neither a whole text nor a
// sentence with its placeholders filled in.
#include "actuator_answer.h"
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "test_wait.h"
#include "widgets/about_dialog.h"
#include "widgets/connect/connect_dialog.h"
#include "widgets/files/new_file_dialog.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/inspector/compose_panel.h"
#include "widgets/inspector/inspector_view.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/monitor/step_control.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QRadioButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTextDocumentFragment>
#include <QWizardPage>
#include <QXmlStreamReader>
#include <gtest/gtest.h>
#include <qcustomplot.h>

namespace vt::test {
namespace {

// An English source of the catalogue whose German differs.
struct Source
{
    QString text;
    // The sentence's own words between its placeholders, when they say it is English
    // ("%1, %2, modules %3" -> "", ", ", ", modules ", ""); empty when not used.
    QStringList pieces;

    // The text is the sentence with its placeholders filled in: it starts with the first piece,
    // ends with the last and holds the others in order (linear; no regular expression).
    bool filledIn(const QString &shown) const
    {
        if (pieces.isEmpty() || !shown.startsWith(pieces.front()) || !shown.endsWith(pieces.back()))
            return false;
        qsizetype at = pieces.front().size();
        for (qsizetype i = 1; i + 1 < pieces.size(); ++i) {
            at = shown.indexOf(pieces[i], at);
            if (at < 0)
                return false;
            at += pieces[i].size();
        }
        return at <= shown.size() - pieces.back().size();
    }
};

// The sentence is only matched when its own words say it is English: a word of four or more
// letters that the German translation does not have ("%1, %2, modules %3" -> "modules").
QStringList sentencePieces(const QString &source, const QString &german)
{
    static const QRegularExpression placeholder(QStringLiteral("%(\\d|n)"));
    if (!source.contains(placeholder))
        return {};
    QString literal = source;
    literal.remove(placeholder);
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{4,}"));
    bool english = false;
    for (auto it = word.globalMatch(literal); it.hasNext();) {
        const QString w = it.next().captured(0);
        english = english || !german.contains(w);
    }
    if (!english)
        return {};
    return source.split(placeholder);
}

std::vector<Source> englishSources()
{
    QFile file(QStringLiteral(VT_SOURCE_DIR "/translations/valvetune_de.ts"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    std::vector<Source> sources;
    QXmlStreamReader xml(&file);
    QString source, translation;
    bool usable = false;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement() && xml.name() == QLatin1String("message")) {
            source.clear();
            translation.clear();
            usable = true;
        } else if (xml.isStartElement() && xml.name() == QLatin1String("source")) {
            source = xml.readElementText();
        } else if (xml.isStartElement() && xml.name() == QLatin1String("translation")) {
            const QString type = xml.attributes().value(QLatin1String("type")).toString();
            usable = type.isEmpty(); // not unfinished, obsolete or vanished
            if (xml.attributes().hasAttribute(QLatin1String("type")) && !usable)
                continue;
            // Plural forms: the first one is enough to tell the languages apart.
            while (!(xml.isEndElement() && xml.name() == QLatin1String("translation")) &&
                   !xml.atEnd()) {
                xml.readNext();
                if (xml.isCharacters() && translation.isEmpty())
                    translation = xml.text().toString();
                if (xml.isStartElement() && xml.name() == QLatin1String("numerusform") &&
                    translation.isEmpty())
                    translation = xml.readElementText();
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            if (usable && !translation.trimmed().isEmpty() && translation != source)
                sources.push_back({source, sentencePieces(source, translation)});
        }
    }
    return sources;
}

void collectItems(const QAbstractItemModel *model, const QModelIndex &parent, QStringList &out,
                  int &budget)
{
    for (int r = 0; r < model->rowCount(parent) && budget > 0; ++r) {
        for (int c = 0; c < model->columnCount(parent); ++c) {
            const QModelIndex i = model->index(r, c, parent);
            out << i.data(Qt::DisplayRole).toString() << i.data(Qt::ToolTipRole).toString();
            --budget;
        }
        collectItems(model, model->index(r, 0, parent), out, budget);
    }
}

void collectMenu(const QList<QAction *> &actions, QStringList &out)
{
    for (const QAction *a : actions) {
        out << a->text() << a->toolTip();
        if (a->menu())
            collectMenu(a->menu()->actions(), out);
    }
}

// Which widget shows a text, for the failure message: "QWizard/QPushButton".
QHash<QString, QString> &shownBy()
{
    static QHash<QString, QString> where;
    return where;
}

// Texts a person sees: titles, labels, buttons, headers, items, tool tips, the status bar, menus.
QStringList visibleTexts()
{
    QStringList out;
    for (QWidget *window : QApplication::topLevelWidgets()) {
        if (!window->isVisible())
            continue;
        out << window->windowTitle();
        QList<QWidget *> widgets = window->findChildren<QWidget *>();
        widgets.prepend(window);
        for (QWidget *w : widgets) {
            if (!w->isVisible())
                continue;
            const qsizetype from = out.size();
            out << w->toolTip() << w->whatsThis();
            if (auto *label = qobject_cast<QLabel *>(w))
                out << (Qt::mightBeRichText(label->text())
                            ? QTextDocumentFragment::fromHtml(label->text()).toPlainText()
                            : label->text());
            if (auto *button = qobject_cast<QAbstractButton *>(w))
                out << button->text();
            if (auto *box = qobject_cast<QGroupBox *>(w))
                out << box->title();
            if (auto *edit = qobject_cast<QLineEdit *>(w))
                out << edit->placeholderText();
            if (auto *dock = qobject_cast<QDockWidget *>(w))
                out << dock->windowTitle();
            if (auto *page = qobject_cast<QWizardPage *>(w))
                out << page->title() << page->subTitle();
            if (auto *combo = qobject_cast<QComboBox *>(w))
                for (int i = 0; i < combo->count(); ++i)
                    out << combo->itemText(i) << combo->itemData(i, Qt::ToolTipRole).toString();
            if (auto *tabs = qobject_cast<QTabBar *>(w))
                for (int i = 0; i < tabs->count(); ++i)
                    out << tabs->tabText(i) << tabs->tabToolTip(i);
            if (auto *bar = qobject_cast<QStatusBar *>(w))
                out << bar->currentMessage();
            if (auto *menus = qobject_cast<QMenuBar *>(w))
                collectMenu(menus->actions(), out);
            if (auto *view = qobject_cast<QAbstractItemView *>(w); view && view->model()) {
                const QAbstractItemModel *m = view->model();
                for (int c = 0; c < m->columnCount(); ++c)
                    out << m->headerData(c, Qt::Horizontal).toString()
                        << m->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString();
                int budget = 3000;
                collectItems(m, view->rootIndex(), out, budget);
            }
            if (auto *plot = qobject_cast<QCustomPlot *>(w)) {
                for (QCPAxis *axis :
                     plot->axisRect() ? plot->axisRect()->axes() : QList<QCPAxis *>())
                    out << axis->label();
                for (int i = 0; i < plot->plottableCount(); ++i)
                    out << plot->plottable(i)->name();
            }
            collectMenu(w->actions(), out);
            const QString path =
                QStringLiteral("%1/%2").arg(QString::fromLatin1(window->metaObject()->className()),
                                            QString::fromLatin1(w->metaObject()->className()));
            for (qsizetype k = from; k < out.size(); ++k)
                for (const QString &line : out[k].split(QLatin1Char('\n')))
                    shownBy().insert(line.trimmed(), path);
        }
    }
    QStringList lines;
    for (const QString &text : out)
        for (const QString &line : text.split(QLatin1Char('\n')))
            if (!line.trimmed().isEmpty())
                lines << line.trimmed();
    lines.removeDuplicates();
    return lines;
}

// Visible texts that are English although the catalogue has them in German.
QStringList englishLeft(const std::vector<Source> &sources)
{
    QHash<QString, QString> whole;
    std::vector<const Source *> sentences;
    for (const Source &s : sources) {
        whole.insert(s.text.trimmed(), s.text);
        if (!s.pieces.isEmpty())
            sentences.push_back(&s);
    }
    QStringList found;
    for (const QString &text : visibleTexts()) {
        if (const auto it = whole.constFind(text); it != whole.constEnd()) {
            found << QStringLiteral("\"%1\" in %2").arg(text, shownBy().value(text));
            continue;
        }
        for (const Source *s : sentences) {
            if (s->filledIn(text)) {
                found << QStringLiteral("\"%1\" (source \"%2\") in %3")
                             .arg(text, s->text, shownBy().value(text));
                break;
            }
        }
    }
    return found;
}

QString tr(const char *context, const char *text)
{
    return QCoreApplication::translate(context, text);
}

TEST(NoEnglishLeft, EveryWindowIsGermanAfterARunTimeSwitch)
{
    ActuatorAnswer yes; // the step and E17 move the valve: answered here
    const std::vector<Source> sources = englishSources();
    ASSERT_GT(sources.size(), 500u); // the catalogue was read

    QTemporaryDir dir;
    app::AppSettings settings(dir.filePath("settings.ini"));
    app::Language language;
    ASSERT_TRUE(language.setLanguage("en"));
    app::MainWindow w(settings, language);
    w.show();
    QSignalSpy read(&w.device(), &app::DeviceController::readFinished);
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = "dma-pn-v51";
    spec.sim.modules = 3;
    spec.sim.factory = true; // E17 = 0: the step asks for E17 first
    w.device().connectTo(spec);
    ASSERT_TRUE(read.wait(kWaitMs));

    // An edit: the Undo action names it.
    const dev::ParamMeta *c107 = w.workspace().document().module(0).dictionary->find("C1.07");
    w.workspace().document().edit(0, c107, 1000.0);

    // A set-value step: E17 first, then A1.01, verified.
    ui::StepControl *step = w.monitor()->stepControl();
    ASSERT_TRUE(step->selectTarget(w.workspace().modules().front().address, "A1.01"));
    step->setStepValue(2.0);
    QSignalSpy written(step, &ui::StepControl::written);
    step->writeStep();
    ASSERT_TRUE(waitUntil([&] { return step->activationOffered(); }));
    step->enableBusSetValue();
    ASSERT_TRUE(written.wait(kWaitMs));
    step->writeStep();
    ASSERT_TRUE(written.wait(kWaitMs));
    ASSERT_TRUE(step->statusText().startsWith("A1.01: verified"))
        << step->statusText().toStdString();

    // A composed read, answered, on the inspector's front tab.
    ui::ComposePanel *compose = w.inspector()->composePanel();
    for (QTabWidget *tabs : w.inspector()->findChildren<QTabWidget *>())
        for (int i = 0; i < tabs->count(); ++i)
            if (tabs->widget(i)->isAncestorOf(compose) || tabs->widget(i) == compose)
                tabs->setCurrentIndex(i);
    compose->setKind(dev::inspect::ComposeKind::GatewayRead);
    compose->setFieldText("sadr", QString::number(w.workspace().modules().front().address));
    compose->setFieldText("id", "7");
    compose->setFieldText("count", "1");
    QSignalSpy answered(compose, &ui::ComposePanel::sendFinished);
    if (compose->send()) {
        ASSERT_TRUE(answered.wait(kWaitMs));
    } else {
        compose->setKind(dev::inspect::ComposeKind::ModbusRead);
        compose->setModbusTcp(w.workspace().connection()->protocolKey() ==
                              QLatin1String("modbus-tcp"));
        compose->setFieldText("unit", QString::number(w.workspace().modules().front().address));
        ASSERT_TRUE(compose->send()) << compose->sendBlockedReason().toStdString();
        ASSERT_TRUE(answered.wait(kWaitMs));
    }
    const QString answeredEnglish = answered.front().front().toString();

    // The fold wizard on its Apply page, which names the connection.
    ui::FoldWizard *wizard = w.openFoldWizard();
    ASSERT_NE(wizard, nullptr);
    ASSERT_TRUE(test::waitUntil([&] { return wizard->isVisible(); }, kWaitMs)); // node read first
    wizard->restart();
    if (auto *dma = wizard->currentPage()->findChild<QRadioButton *>(QStringLiteral("dma-pn")))
        dma->click();
    while (wizard->currentId() != ui::FoldWizard::ApplyPageId) {
        const int before = wizard->currentId();
        wizard->next();
        if (wizard->currentId() == before)
            break;
    }
    EXPECT_EQ(wizard->currentId(), ui::FoldWizard::ApplyPageId);

    // Every dock on its own, so that none hides behind another's tab.
    for (QDockWidget *dock : w.findChildren<QDockWidget *>()) {
        dock->setFloating(true);
        dock->show();
    }

    // The dialogs the window reaches, open side by side.
    auto *connectDialog = new ui::ConnectDialog(w.workspace().dictionaries(), nullptr, &w);
    connectDialog->show();
    auto *newFile = new ui::NewFileDialog(w.workspace().dictionaries(), &w);
    newFile->show();
    auto *about = new ui::AboutDialog(&w);
    about->show();
    QCoreApplication::processEvents();
    // In English, the run-time texts are there to be found (the check can fail).
    const QStringList before = englishLeft(sources);
    EXPECT_GT(before.size(), 20);
    for (const char *expected : {"modules 1, 2, 3", "A1.01: verified", "Answered:", "Undo: module"})
        EXPECT_TRUE(visibleTexts().filter(QLatin1String(expected)).size() > 0) << expected;

    w.findChild<QAction *>("actionGerman")->trigger();
    QCoreApplication::processEvents();

    const QStringList left = englishLeft(sources);
    EXPECT_TRUE(left.isEmpty()) << left.join(QLatin1Char('\n')).toStdString();
    const QStringList german = visibleTexts();
    EXPECT_GT(german.filter(QLatin1String("Module 1, 2, 3")).size(), 0);
    EXPECT_GT(german.filter(tr("vt::model::WriteJob", "verified")).size(), 0);
    EXPECT_NE(tr("vt::model::WriteJob", "verified"), QLatin1String("verified"));
    EXPECT_TRUE(step->statusText().startsWith(QStringLiteral("A1.01: ") +
                                              tr("vt::model::WriteJob", "verified")));
    EXPECT_EQ(german.filter(answeredEnglish).size(), 0) << answeredEnglish.toStdString();
}

// The E17 hint quotes the manuals; in German it quotes the German DMA manual's words.
TEST(NoEnglishLeft, TheE17HintQuotesTheManualInTheUiLanguage)
{
    ActuatorAnswer yes; // the step and E17 move the valve: answered here
    QTemporaryDir dir;
    app::AppSettings settings(dir.filePath("settings.ini"));
    app::Language language;
    ASSERT_TRUE(language.setLanguage("de"));
    app::MainWindow w(settings, language);
    w.show();
    QSignalSpy read(&w.device(), &app::DeviceController::readFinished);
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = "dma-pn-v51";
    spec.sim.factory = true; // E17 = 0: the hint is shown
    w.device().connectTo(spec);
    ASSERT_TRUE(read.wait(kWaitMs));
    ui::StepControl *step = w.monitor()->stepControl();
    ASSERT_TRUE(step->selectTarget(w.workspace().modules().front().address, "A1.01"));
    step->setStepValue(2.0);
    step->writeStep();
    ASSERT_TRUE(waitUntil([&] { return step->activationOffered(); }));
    // DMA Profinet manual, ID 0x1F (A1.01): a Profinet node cites its own manual in German too.
    EXPECT_TRUE(step->statusText().contains("Zum Abschalten des analogen Sollwert"))
        << step->statusText().toStdString();
    EXPECT_TRUE(step->statusText().contains("DMA-Profinet-Handbuch"))
        << step->statusText().toStdString();
    EXPECT_FALSE(step->statusText().contains("Profibus")) << step->statusText().toStdString();
    EXPECT_FALSE(step->statusText().contains("For switching off"))
        << step->statusText().toStdString();

    w.findChild<QAction *>("actionEnglish")->trigger();
    QCoreApplication::processEvents();
    EXPECT_TRUE(step->statusText().contains("For switching off of the analogue set-value"))
        << step->statusText().toStdString();
}

} // namespace
} // namespace vt::test
