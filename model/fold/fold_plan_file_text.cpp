#include "fold_plan_file.h"

#include <QCoreApplication>
#include <QString>

namespace vt::model {
namespace {

class FoldFileText
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::FoldPlanFile)

public:
    static QString damaged(const FoldFileError &e)
    {
        const QString member = QString::fromStdString(e.member);
        switch (e.problem) {
        case FoldFileProblem::NotWholeNumber:
            return tr("The fold plan file is damaged: %1 is not a whole number.").arg(member);
        case FoldFileProblem::OutOfBounds:
            return tr("The fold plan file is damaged: %1 is outside %2 … %3.")
                .arg(member)
                .arg(e.low)
                .arg(e.high);
        case FoldFileProblem::NotText:
            return tr("The fold plan file is damaged: %1 is not a text.").arg(member);
        case FoldFileProblem::TooLong:
            return tr("The fold plan file is damaged: %1 is longer than %2 bytes.")
                .arg(member)
                .arg(e.high);
        case FoldFileProblem::UnknownNode:
            return tr("The fold plan file is damaged: %1 is not opat, dma-pb or dma-pn.")
                .arg(member);
        case FoldFileProblem::NotList:
            return tr("The fold plan file is damaged: %1 is not a list.").arg(member);
        case FoldFileProblem::TooManyEntries:
            return tr("The fold plan file is damaged: %1 has more than %2 entries.")
                .arg(member)
                .arg(e.high);
        case FoldFileProblem::NotObject:
            return tr("The fold plan file is damaged: %1 is not an object.").arg(member);
        default: return tr("The fold plan file is damaged: %1.").arg(member);
        }
    }

    static QString text(const FoldFileError &e)
    {
        switch (e.code) {
        case FoldFileErrc::TooLarge:
            return tr("The file is larger than %1 KiB; it is not a fold plan.")
                .arg(static_cast<qulonglong>(kFoldPlanMaxBytes / 1024));
        case FoldFileErrc::NotJson:
            return e.problem == FoldFileProblem::NumberTooLarge
                       ? tr("The file is not valid JSON (a number is out of range).")
                       : tr("The file is not valid JSON (byte %1).")
                             .arg(static_cast<qulonglong>(e.offset));
        case FoldFileErrc::WrongFormat:
            return e.problem == FoldFileProblem::TooDeep
                       ? tr("The file is nested too deeply to be a fold plan.")
                       : tr("The file is not a ValveTune fold plan.");
        case FoldFileErrc::NewerVersion:
            return tr("The fold plan was written by a newer ValveTune (format version %1); this "
                      "version reads format %2.")
                .arg(e.high)
                .arg(kFoldPlanVersion);
        case FoldFileErrc::MissingMember:
            return tr("The fold plan file is incomplete: %1 is missing.")
                .arg(QString::fromStdString(e.member));
        case FoldFileErrc::BadMember: return damaged(e);
        case FoldFileErrc::Io:
            return e.problem == FoldFileProblem::WriteFailed
                       ? tr("The fold plan file cannot be written: %1")
                             .arg(QString::fromStdString(e.path))
                       : tr("The fold plan file cannot be read: %1")
                             .arg(QString::fromStdString(e.path));
        }
        return {};
    }
};

} // namespace

QString foldFileErrorText(const FoldFileError &error)
{
    return FoldFileText::text(error);
}

} // namespace vt::model
