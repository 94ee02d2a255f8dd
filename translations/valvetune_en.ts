<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
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
</TS>
