// CompareModel: the differences between the open document and another side — the connected
// device (its last read values) or another parameter file — one row per settable parameter that
// differs, with a per-row choice to take the other side's value into the document (one undo
// step). Writing the document to the device stays the editor's Write changes. GUI thread.
#pragma once

#include "model/params/parameter_document.h"

#include <QAbstractTableModel>

namespace vt::model {

class CompareModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { ColModule, ColName, ColLabel, ColThis, ColOther, ColTake, ColumnCount };
    enum class Other { Device, File };

    explicit CompareModel(ParameterDocument &document, QObject *parent = nullptr);

    // Compare with the device layer of the document.
    void compareWithDevice();
    // Compare with another file: its modules pair with the document's by address and family (a
    // one-module file with a one-module document regardless of address).
    void compareWithFile(const dev::files::ParamFile &file, const QString &name);
    // Recomputes the rows (after an apply or new device values).
    void refresh();

    Other other() const { return m_other; }
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    void setAllTaken(bool take);
    int takenCount() const;
    // Takes the other side's value of every checked row into the document; returns how many.
    int applyTaken();

private:
    struct Row
    {
        int module = 0;
        const dev::ParamMeta *meta = nullptr;
        std::optional<dev::RawValue> mine, theirs;
        bool take = false;
    };
    std::optional<dev::RawValue> otherValue(int module, const dev::ParamMeta *row) const;

    ParameterDocument &m_document;
    Other m_other = Other::Device;
    QString m_otherName;
    // Other file: values per document module index.
    std::map<int, std::map<const dev::ParamMeta *, dev::RawValue>> m_fileValues;
    std::vector<Row> m_rows;
};

} // namespace vt::model
