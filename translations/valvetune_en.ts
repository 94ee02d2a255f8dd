<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>FoldBenchPage</name>
    <message numerus="yes">
        <source>%1 (%n answer(s))</source>
        <translation>
            <numerusform>%1 (%n answer)</numerusform>
            <numerusform>%1 (%n answers)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FoldCheckPage</name>
    <message numerus="yes">
        <source>%n error(s) must be fixed before the plan can be applied; go Back to change it.</source>
        <translation>
            <numerusform>%n error must be fixed before the plan can be applied; go Back to change it.</numerusform>
            <numerusform>%n errors must be fixed before the plan can be applied; go Back to change them.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>No errors; %n warning(s) to read.</source>
        <translation>
            <numerusform>No errors; %n warning to read.</numerusform>
            <numerusform>No errors; %n warnings to read.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FoldModulesPage</name>
    <message numerus="yes">
        <source>Scan finished: %n module(s) at address %1.</source>
        <translation>
            <numerusform>Scan finished: %n module at address %1.</numerusform>
            <numerusform>Scan finished: %n modules at addresses %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::app::DeviceController</name>
    <message numerus="yes">
        <source>Scan found %n module(s).</source>
        <translation>
            <numerusform>Scan found %n module.</numerusform>
            <numerusform>Scan found %n modules.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::app::MainWindow</name>
    <message numerus="yes">
        <source>Connected: %n module(s).</source>
        <translation>
            <numerusform>Connected: %n module.</numerusform>
            <numerusform>Connected: %n modules.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The fold wizard read %n module(s) of the connected node.</source>
        <translation>
            <numerusform>The fold wizard read %n module of the connected node.</numerusform>
            <numerusform>The fold wizard read %n modules of the connected node.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::model::FoldSheetText</name>
    <message numerus="yes">
        <source>Fold plan: %1 (%2), %n module(s)</source>
        <translation>
            <numerusform>Fold plan: %1 (%2), %n module</numerusform>
            <numerusform>Fold plan: %1 (%2), %n modules</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::model::ParameterDocument</name>
    <message numerus="yes">
        <source>%1 takes at most %n character(s).</source>
        <translation>
            <numerusform>%1 takes at most %n character.</numerusform>
            <numerusform>%1 takes at most %n characters.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::model::ParameterTreeModel</name>
    <message numerus="yes">
        <source>text, at most %n characters</source>
        <translation>
            <numerusform>text, at most %n character</numerusform>
            <numerusform>text, at most %n characters</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n choices</source>
        <translation>
            <numerusform>%n choice</numerusform>
            <numerusform>%n choices</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n second(s) ago</source>
        <translation>
            <numerusform>%n second ago</numerusform>
            <numerusform>%n seconds ago</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n minute(s) ago</source>
        <translation>
            <numerusform>%n minute ago</numerusform>
            <numerusform>%n minutes ago</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::model::ReadAllJob</name>
    <message numerus="yes">
        <source>Module %1: %n rows not read (%2)</source>
        <translation>
            <numerusform>Module %1: %n row not read (%2)</numerusform>
            <numerusform>Module %1: %n rows not read (%2)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::model::Session</name>
    <message numerus="yes">
        <source>No answer after %n attempt(s)</source>
        <translation>
            <numerusform>No answer after %n attempt</numerusform>
            <numerusform>No answer after %n attempts</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::model::TelegramLog</name>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n byte</numerusform>
            <numerusform>%n bytes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>ValveTune telegram log: %n record(s)</source>
        <translation>
            <numerusform>ValveTune telegram log: %n record</numerusform>
            <numerusform>ValveTune telegram log: %n records</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n older record(s) dropped</source>
        <translation>
            <numerusform>%n older record dropped</numerusform>
            <numerusform>%n older records dropped</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::ui::CompareDialog</name>
    <message numerus="yes">
        <source>%n parameter(s) differ. Tick &quot;Take other&quot; for each value to take into this document.</source>
        <translation>
            <numerusform>%n parameter differs. Tick &quot;Take other&quot; for each value to take into this document.</numerusform>
            <numerusform>%n parameters differ. Tick &quot;Take other&quot; for each value to take into this document.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Apply %n Ticked Value(s)</source>
        <translation>
            <numerusform>Apply %n Ticked Value</numerusform>
            <numerusform>Apply %n Ticked Values</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Apply puts %n ticked value(s) into this document as one step (Edit ▸ Undo takes it back). Nothing is written to the device until Device ▸ Write Changes.</source>
        <translation>
            <numerusform>Apply puts %n ticked value into this document as one step (Edit ▸ Undo takes it back). Nothing is written to the device until Device ▸ Write Changes.</numerusform>
            <numerusform>Apply puts %n ticked values into this document as one step (Edit ▸ Undo takes it back). Nothing is written to the device until Device ▸ Write Changes.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::ui::DecodePanel</name>
    <message numerus="yes">
        <source>%n byte(s).</source>
        <translation>
            <numerusform>%n byte.</numerusform>
            <numerusform>%n bytes.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::ui::MapReportDialog</name>
    <message numerus="yes">
        <source>Module %1: family &quot;%2&quot; is not known to this version; its %n value(s) are kept and saved unchanged.</source>
        <translation>
            <numerusform>Module %1: family &quot;%2&quot; is not known to this version; its %n value is kept and saved unchanged.</numerusform>
            <numerusform>Module %1: family &quot;%2&quot; is not known to this version; its %n values are kept and saved unchanged.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::ui::NewFileDialog</name>
    <message numerus="yes">
        <source>%n module(s): %1. Values start at the dictionary&apos;s defaults.</source>
        <translation>
            <numerusform>%n module: %1. Values start at the dictionary&apos;s defaults.</numerusform>
            <numerusform>%n modules: %1. Values start at the dictionary&apos;s defaults.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::ui::ReferenceDriftView</name>
    <message numerus="yes">
        <source>%n setting(s) differ from the reference.</source>
        <translation>
            <numerusform>%n setting differs from the reference.</numerusform>
            <numerusform>%n settings differ from the reference.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::ui::WriteDialog</name>
    <message numerus="yes">
        <source>%n change(s) will be written to the device, one at a time, each read back.</source>
        <translation>
            <numerusform>%n change will be written to the device and read back.</numerusform>
            <numerusform>%n changes will be written to the device, one at a time, each read back.</numerusform>
        </translation>
    </message>
</context>
</TS>
