// Linked into every test binary: the session logs (model/audit) of the writes a test makes — in
// process or in a valvetune-cli it starts — go to a temporary folder removed when the binary
// ends, never to the user's ~/.local/share/ValveTune/sessions. A test that names its own folder
// (--audit-dir, an AuditLog of its own) is not affected.
#include <QByteArray>
#include <QFile>
#include <QTemporaryDir>
#include <QtGlobal>

namespace {

struct TestSessions
{
    QTemporaryDir dir;
    TestSessions()
    {
        if (qEnvironmentVariableIsEmpty("VT_AUDIT_DIR") && dir.isValid())
            qputenv("VT_AUDIT_DIR", QFile::encodeName(dir.path()));
    }
};

const TestSessions g_testSessions;

} // namespace
