// ParameterDocument: the parameters of every module on screen — from the connected node, an open
// .vtpar file or File ▸ New — as file and working values (param_module.h), with undo for every
// edit, the rows a safe write must send, and the ParamFile that Save writes. What the device
// holds is read from the DeviceImage the document is paired with, never copied: a document is
// never the device. The tree and compare models and the editor widgets all work on one document.
// GUI thread.
#pragma once

#include "core/local_text.h"
#include "model/params/new_file.h"
#include "model/params/param_module.h"
#include "model/params/value_commands.h"
#include "model/session/device_access.h"
#include "model/session/device_image.h"
#include "model/session/write_record.h"

#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QUndoStack>
#include <vector>

namespace vt::model {

class ParameterDocument : public QObject
{
    Q_OBJECT
public:
    explicit ParameterDocument(QObject *parent = nullptr);
    ~ParameterDocument() override;

    QUndoStack *undoStack() { return &m_undo; }
    const std::vector<ParamModule> &modules() const { return m_modules; }
    const ParamModule &module(int index) const
    {
        return m_modules.at(static_cast<std::size_t>(index));
    }
    int moduleCount() const { return static_cast<int>(m_modules.size()); }
    int findModule(int address) const; // -1 when absent

    // Texts and numbers of the models follow this ("1,000 V" in German).
    dev::Language language() const { return m_language; }
    void setLanguage(dev::Language language);

    // --- structure ----------------------------------------------------------------------------
    // Empties the document (no file, no modules, undo history cleared).
    void clear();
    // File ▸ New: the modules of the choice with the dictionary's defaults (newParamFile), no file
    // path yet (Save asks for one).
    void createNew(const NewFileChoice &choice, const dev::DictionarySet &dictionaries);
    // The device image the Device column reads (the connection's). Without one the document
    // keeps an empty image of its own.
    void setDeviceImage(DeviceImage *image);
    const DeviceImage &deviceImage() const { return m_image ? *m_image : m_ownImage; }
    // The identified modules of a connection: a module of the document with the same address and
    // family becomes online (paired); with `addMissing`, device modules the document lacks are
    // added (connecting to a node shows the node), otherwise they stay out (a file or New while
    // connected shows the document's modules). Returns what paired with what, for people.
    QStringList attachDevice(const std::vector<ModuleInfo> &modules, bool addMissing = true);
    // All modules offline; the Device column keeps the last known values, shown as not current.
    void detachDevice();
    // Replaces the document with a loaded file (each record mapped onto its family's dictionary;
    // the reports say what did not map). Undo history is cleared. Records of a family the set does
    // not know are kept for saving and listed in `unknownFamilies`.
    void loadFile(const dev::files::ParamFile &file, const dev::DictionarySet &dictionaries,
                  const QString &path);
    const QString &filePath() const { return m_filePath; }
    bool hasFile() const { return !m_filePath.isEmpty(); }
    const std::vector<dev::files::ModuleRecord> &unknownFamilies() const { return m_unmapped; }
    // What Save writes: every module's working values, plus everything the file had that this
    // version does not apply, written back unchanged.
    dev::files::ParamFile toParamFile(const std::string &tool) const;
    // After a successful save to `path`: the file layer becomes the working values; clean state.
    void markSaved(const QString &path);
    // Unsaved user edits (undo history not at its clean state).
    bool isModified() const { return !m_undo.isClean(); }

    // --- values -------------------------------------------------------------------------------
    std::optional<dev::RawValue> value(int module, const dev::ParamMeta *row,
                                       Layer layer = Layer::Working) const;
    // A user edit (undoable). Refused, with a sentence that names the row, for read-only rows,
    // values of the wrong type and values out of range (the limits named in display units). The
    // sentence is in the language shown now (the dictionary's words in language()): the editor
    // shows it at once.
    std::optional<QString> edit(int module, const dev::ParamMeta *row, const dev::RawValue &value);
    // Several rows as one undo step (Revert, Apply from compare); no checks beyond the row's type.
    struct Change
    {
        int module = 0;
        const dev::ParamMeta *row = nullptr;
        std::optional<dev::RawValue> value;
    };
    void editMany(const std::vector<Change> &changes, UndoText undoText);
    // Several number rows of one module as one undo step (a drag on the L curve).
    void editNumbers(int module,
                     const std::vector<std::pair<const dev::ParamMeta *, double>> &values,
                     UndoText undoText);
    // Used by the undo commands: sets the working value without recording.
    void setWorking(int module, const dev::ParamMeta *row,
                    const std::optional<dev::RawValue> &value);

    // Device values arrive through the image: read-only rows and rows the user has not changed
    // follow the device; a file's values stay (the "differs from device" filter shows them).

    // Is the device's value of this row known now (this connection, not too old)?
    bool deviceCurrent(int module, const dev::ParamMeta *row) const;
    // The rows a safe write or a compare must read first: settings of an online module with a
    // working value whose device value is not current.
    std::vector<const dev::ParamMeta *> rowsToRead(int module) const;
    // The safe write's rows: writable, active settings whose working value differs from the
    // device's current value, in dictionary order, with `before` set; rows whose device value is
    // not current are listed too (before unset) — read them first (rowsToRead) so none are.
    std::vector<WriteItem> pendingWrites(int module) const;
    // Rows whose working value differs from the device's last known value (filters, Revert).
    bool differsFromDevice(int module, const dev::ParamMeta *row) const;
    // Working value differs from the file's (or, with no file value, from the device's).
    bool changed(int module, const dev::ParamMeta *row) const;

    void revertToDevice();
    void revertToFile();

signals:
    // Modules added or removed, or a file loaded: views rebuild.
    void modulesReset();
    // A module's identity or online state changed (not its rows).
    void moduleChanged(int module);
    // One row's value in any layer changed.
    void valueChanged(int module, const dev::ParamMeta *row);
    // Many rows of a module changed at once (a read, a revert).
    void moduleValuesChanged(int module);
    void languageChanged();
    void filePathChanged(const QString &path);

private:
    void resetModules(std::vector<ParamModule> modules);
    void onImageChanged(int address, const std::vector<ImageChange> &changes);
    void onCurrencyChanged();

    std::vector<ParamModule> m_modules;
    std::vector<dev::files::ModuleRecord> m_unmapped;
    dev::files::ParamFile m_fileHeader; // note, tool, created, unknown keys of the loaded file
    QString m_filePath;
    dev::Language m_language = dev::Language::English;
    QUndoStack m_undo;
    DeviceImage m_ownImage;
    QPointer<DeviceImage> m_image; // null: m_ownImage
};

} // namespace vt::model
