<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>vt::app::MainWindow</name>
    <message>
        <source>ValveTune</source>
        <translation>ValveTune</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Device</source>
        <translation>&amp;Gerät</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;New…</source>
        <translation>&amp;Neu…</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportieren…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation>&amp;Verbinden…</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <source>&amp;Read All</source>
        <translation>Alle &amp;lesen</translation>
    </message>
    <message>
        <source>&amp;Write Changes…</source>
        <translation>Änderungen &amp;schreiben…</translation>
    </message>
    <message>
        <source>&amp;Scan Node</source>
        <translation>Knoten &amp;abfragen</translation>
    </message>
    <message>
        <source>&amp;Fold Wizard…</source>
        <translation>&amp;Knoten-Assistent…</translation>
    </message>
    <message>
        <source>&amp;About ValveTune…</source>
        <translation>Ü&amp;ber ValveTune…</translation>
    </message>
    <message>
        <source>Not available in this version yet</source>
        <translation>In dieser Version noch nicht verfügbar</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Monitor</source>
        <translation>Monitor</translation>
    </message>
    <message>
        <source>Telegrams</source>
        <translation>Telegramme</translation>
    </message>
    <message>
        <source>The parameters of the connected device or the open file appear here.</source>
        <translation>Hier erscheinen die Parameter des verbundenen Geräts oder der geöffneten Datei.</translation>
    </message>
    <message>
        <source>Live values of the connected device are plotted here.</source>
        <translation>Hier werden die Live-Werte des verbundenen Geräts aufgezeichnet.</translation>
    </message>
    <message>
        <source>Every telegram sent and received is listed here.</source>
        <translation>Hier wird jedes gesendete und empfangene Telegramm aufgelistet.</translation>
    </message>
    <message>
        <source>No device connected and no parameter file open.</source>
        <translation>Kein Gerät verbunden und keine Parameterdatei geöffnet.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Clear List</source>
        <translation>Liste leeren</translation>
    </message>
</context>
<context>
    <name>vt::link::Link</name>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Verbinde…</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>Verbunden</translation>
    </message>
    <message>
        <source>Connection failed</source>
        <translation>Verbindung fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>vt::ui::AboutDialog</name>
    <message>
        <source>About ValveTune</source>
        <translation>Über ValveTune</translation>
    </message>
    <message>
        <source>ValveTune %1

Parameterisation, tuning and commissioning of hydraulic proportional-valve electronics: HCS OPAT and DMA-2, Wandfluh ED1/SD1 (DSP-408) and SD7 (HART-7).

Licensed under the GNU General Public License, version 3 or later. Plots use QCustomPlot (GPL-3.0).</source>
        <translation>ValveTune %1

Parametrierung, Optimierung und Inbetriebnahme von Elektroniken für hydraulische Proportionalventile: HCS OPAT und DMA-2, Wandfluh ED1/SD1 (DSP-408) und SD7 (HART-7).

Lizenziert unter der GNU General Public License, Version 3 oder später. Die Diagramme verwenden QCustomPlot (GPL-3.0).</translation>
    </message>
</context>
</TS>
