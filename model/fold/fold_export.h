// Printable PLC sheets of a fold plan: HTML for the browser/printer, PDF
// rendered offscreen through QTextDocument + QPdfWriter (QtGui only), and CSV of the byte maps.
#pragma once

// clang-format off
// First: devices/hcs/status_bits.h (via plc_config.h) has a member named `signals`, which Qt's
// keyword macro would rewrite once a Qt header defined it.
#include "plc_config.h"
// clang-format on
#include "core/local_text.h"
#include "fold_check.h"
#include "fold_plan.h"

#include <QString>
#include <optional>
#include <vector>

namespace vt::model {

struct FoldSheet
{
    FoldPlan plan;
    PlcConfig config;                  // buildPlcConfig(plan).value()
    std::vector<FoldFinding> findings; // checkFoldPlan(plan); shown at the top when not empty
};

// Builds the plan's config and findings; nullopt (with *why set) when buildPlcConfig fails.
std::optional<FoldSheet> makeFoldSheet(const FoldPlan &plan, PlcText *why = nullptr);

// Self-contained HTML 4 document (inline CSS, no scripts, no external files), text escaped.
// Sections: node and GSD, modules and addresses, findings, output image, input image, per-module
// bits, example telegram. Numbers are plain (byte offsets, hex), so the sheet reads the same in
// both languages apart from the words. The sheet's words and the findings go through tr() (the
// catalogue in force); the plan's {en, de} texts are shown in `lang` (the wizard passes the
// language shown, so both agree).
QString foldSheetHtml(const FoldSheet &sheet, dev::Language lang);

// One row per image byte: direction;offset;module;sadr;field;meaning — ';' separated, fields
// quoted when needed, UTF-8 with a header row. Language picks the meaning column's words.
QString foldSheetCsv(const FoldSheet &sheet, dev::Language lang);

// Renders foldSheetHtml to an A4 PDF at `path`; works with QT_QPA_PLATFORM=offscreen. Returns the
// page count (> 0) or nullopt when the file could not be written.
std::optional<int> writeFoldSheetPdf(const FoldSheet &sheet, dev::Language lang,
                                     const QString &path);

// Plain-text sheet (the CLI's `fold plan` output and the wizard's copy-to-clipboard).
QString foldSheetText(const PlcConfig &config, const FoldPlan &plan, dev::Language lang);

} // namespace vt::model
