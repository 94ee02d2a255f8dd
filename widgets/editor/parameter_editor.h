// ParameterEditor: the screen an engineer lives in — the parameter tree of every module with
// search, the filters "changed only", "differs from device" and "show inactive", value editors
// from the metadata, the help text of the selected parameter beside it, and the reason when an
// entry is refused. Works on a ParameterDocument it does not own. GUI thread.
#pragma once

#include "dict/param_meta.h"

#include <QSet>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QSplitter;
class QTextBrowser;
class QTreeView;

namespace vt::model {
class ParameterDocument;
class ParameterFilterModel;
class ParameterTreeModel;
} // namespace vt::model

namespace vt::ui {

class ParameterEditor : public QWidget
{
    Q_OBJECT
public:
    explicit ParameterEditor(model::ParameterDocument &document, QWidget *parent = nullptr);
    ~ParameterEditor() override;

    QTreeView *view() const { return m_view; }
    model::ParameterTreeModel *treeModel() const { return m_tree; }
    model::ParameterFilterModel *filterModel() const { return m_filter; }
    QLineEdit *searchBox() const { return m_search; }
    QLabel *messageLabel() const { return m_message; }
    QTextBrowser *helpPane() const { return m_help; }

    // Selects (and scrolls to) a parameter, clearing a search that hides it.
    bool selectParameter(int module, const dev::ParamMeta *row);
    // The selected parameter (module index and row), or {-1, nullptr}.
    std::pair<int, const dev::ParamMeta *> currentParameter() const;
    // F1: the help of the selected parameter in the pane beside the tree, opening the pane.
    void showHelpOfCurrent();

signals:
    void parameterSelected(int module, const dev::ParamMeta *row);
    // The user asked for the telegrams that carried the selected parameter.
    void showFramesRequested(int module, const QString &parameterName);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateColumns();
    void onCurrentChanged(const QModelIndex &current);
    void expandDefault();
    void fitValueColumns();
    QString expansionKey(const QModelIndex &proxy) const;
    void restoreExpansion();

    model::ParameterDocument &m_document;
    model::ParameterTreeModel *m_tree = nullptr;
    model::ParameterFilterModel *m_filter = nullptr;
    QTreeView *m_view = nullptr;
    QLineEdit *m_search = nullptr;
    QCheckBox *m_changedOnly = nullptr;
    QCheckBox *m_differsOnly = nullptr;
    QCheckBox *m_showInactive = nullptr;
    QLabel *m_message = nullptr;
    QTextBrowser *m_help = nullptr;
    QSplitter *m_splitter = nullptr;
    QSet<QString> m_expanded; // source row paths of the rows the user keeps open
    bool m_restoring = false;
    bool m_restorePending = false;
};

} // namespace vt::ui
