// The German catalogue is complete: every message translated, none unfinished, vanished or
// obsolete. lupdate marks new UI strings "unfinished", so a change
// that adds text without translating it fails here.
#include "qt_printers.h"

#include <QFile>
#include <QXmlStreamReader>
#include <gtest/gtest.h>

TEST(Translations, GermanCatalogueHasNoUnfinishedEntries)
{
    QFile file(QStringLiteral(VT_SOURCE_DIR "/translations/valvetune_de.ts"));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QXmlStreamReader xml(&file);
    int messages = 0;
    QString source;
    QStringList problems;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == QLatin1String("source")) {
            source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
            ++messages;
            const QString type = xml.attributes().value(QLatin1String("type")).toString();
            const bool plural =
                xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            if (!type.isEmpty() || (!plural && text.trimmed().isEmpty()))
                problems << QStringLiteral("%1 [%2]").arg(source, type.isEmpty() ? "empty" : type);
        }
    }
    ASSERT_FALSE(xml.hasError()) << xml.errorString().toStdString();
    EXPECT_GT(messages, 30);
    EXPECT_TRUE(problems.isEmpty()) << problems.join('\n').toStdString();
}
