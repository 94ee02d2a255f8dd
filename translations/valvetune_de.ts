<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>AnalysisTexts</name>
    <message>
        <source>no figures: too few samples in the hold</source>
        <translation>keine Kennwerte: zu wenige Messwerte im Halteabschnitt</translation>
    </message>
    <message>
        <source>no figures: the hold is too short</source>
        <translation>keine Kennwerte: Haltezeit zu kurz</translation>
    </message>
    <message>
        <source>no figures: no step</source>
        <translation>keine Kennwerte: kein Sprung</translation>
    </message>
    <message>
        <source>no figures: the response did not move</source>
        <translation>keine Kennwerte: die Antwort hat sich nicht bewegt</translation>
    </message>
    <message>
        <source>no figures: not settled by the end of the hold</source>
        <translation>keine Kennwerte: bis zum Ende der Haltezeit nicht eingeschwungen</translation>
    </message>
    <message>
        <source>no: not measurable</source>
        <translation>nein: nicht messbar</translation>
    </message>
    <message>
        <source>no: outside the recording</source>
        <translation>nein: außerhalb der Aufzeichnung</translation>
    </message>
    <message>
        <source>no: too few samples</source>
        <translation>nein: zu wenige Messwerte</translation>
    </message>
    <message>
        <source>no: the set value did not move</source>
        <translation>nein: der Sollwert hat sich nicht bewegt</translation>
    </message>
    <message>
        <source>no: above the valid band</source>
        <translation>nein: oberhalb des gültigen Bereichs</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>ValveTune cannot start with this command line:</source>
        <translation>ValveTune kann mit dieser Befehlszeile nicht starten:</translation>
    </message>
    <message>
        <source>Run &quot;valvetune --help&quot; in a terminal for the options.</source>
        <translation>&quot;valvetune --help&quot; in einem Terminal zeigt die Optionen.</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1 is larger than 256 MiB.</source>
        <translation>%1 ist größer als 256 MiB.</translation>
    </message>
    <message>
        <source>step %1 → %2 %3</source>
        <translation>Sprung %1 → %2 %3</translation>
    </message>
    <message>
        <source>sweep %1 … %2 Hz</source>
        <translation>Sweep %1 … %2 Hz</translation>
    </message>
    <message>
        <source>%1 %2 Hz ± %3 %4</source>
        <translation>%1 %2 Hz ± %3 %4</translation>
    </message>
    <message>
        <source>Run %1 · %2 · module %3 %4</source>
        <translation>Lauf %1 · %2 · Modul %3 %4</translation>
    </message>
    <message>
        <source>%1 is not a readable run: %2</source>
        <translation>%1 ist kein lesbarer Lauf: %2</translation>
    </message>
    <message>
        <source>%1 is a run of %2, a family this ValveTune does not know.</source>
        <translation>%1 ist ein Lauf von %2, einer Gerätefamilie, die dieses ValveTune nicht kennt.</translation>
    </message>
    <message>
        <source>%1 is not a readable reference: %2</source>
        <translation>%1 ist keine lesbare Referenz: %2</translation>
    </message>
    <message>
        <source>%1 is a reference of %2, a family this ValveTune does not know.</source>
        <translation>%1 ist eine Referenz von %2, einer Gerätefamilie, die dieses ValveTune nicht kennt.</translation>
    </message>
    <message>
        <source>%1: test %2: %3</source>
        <translation>%1: Test %2: %3</translation>
    </message>
    <message>
        <source>The reference was taken on a %1 module; module %2 is a %3.</source>
        <translation>Die Referenz wurde an einem %1-Modul aufgenommen; Modul %2 ist ein %3.</translation>
    </message>
    <message>
        <source>The reference was taken in mode %1; module %2 runs in mode %3: its set values and responses are other rows.</source>
        <translation>Die Referenz wurde in Modus %1 aufgenommen; Modul %2 läuft in Modus %3: Sollwerte und Antworten sind dort andere Zeilen.</translation>
    </message>
    <message>
        <source>Module %1 has no set value %2 a test can drive.</source>
        <translation>Modul %1 hat keinen Sollwert %2, den ein Test vorgeben kann.</translation>
    </message>
    <message>
        <source>The reference was taken with software %1; the module has %2.</source>
        <translation>Die Referenz wurde mit Software %1 aufgenommen; das Modul hat %2.</translation>
    </message>
    <message>
        <source>The reference was taken at address %1; this module is at %2.</source>
        <translation>Die Referenz wurde an Adresse %1 aufgenommen; dieses Modul hat Adresse %2.</translation>
    </message>
    <message>
        <source>It names a signal or a set value that does not exist.</source>
        <translation>Sie nennt ein Signal oder einen Sollwert, den es nicht gibt.</translation>
    </message>
    <message>
        <source>It records %1, which %2 does not have.</source>
        <translation>Sie zeichnet %1 auf, das %2 nicht hat.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>vt::app::DeviceController</name>
    <message>
        <source>Scanning the node…</source>
        <translation>Knoten wird abgefragt…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message numerus="yes">
        <source>Scan found %n module(s).</source>
        <translation>
            <numerusform>Abfrage: %n Modul gefunden.</numerusform>
            <numerusform>Abfrage: %n Module gefunden.</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading all parameters…</source>
        <translation>Alle Parameter werden gelesen…</translation>
    </message>
    <message>
        <source>All parameters read.</source>
        <translation>Alle Parameter gelesen.</translation>
    </message>
    <message>
        <source>Read incomplete: %1</source>
        <translation>Lesen unvollständig: %1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>Nothing to write: the editor and the device agree.</source>
        <translation>Nichts zu schreiben: Editor und Gerät stimmen überein.</translation>
    </message>
    <message>
        <source>Every change written and verified.</source>
        <translation>Alle Änderungen geschrieben und geprüft.</translation>
    </message>
    <message>
        <source>Not every change reached the device; see the write results.</source>
        <translation>Nicht alle Änderungen haben das Gerät erreicht; siehe Schreibergebnisse.</translation>
    </message>
    <message>
        <source>Connection Failed</source>
        <translation>Verbindung fehlgeschlagen</translation>
    </message>
    <message>
        <source>ValveTune could not connect: %1</source>
        <translation>ValveTune konnte keine Verbindung herstellen: %1</translation>
    </message>
    <message>
        <source>Before disconnecting:</source>
        <translation>Vor dem Trennen:</translation>
    </message>
    <message>
        <source>Module %1: %2 cannot be put back: its value before the change was never read.</source>
        <translation>Modul %1: %2 kann nicht zurückgesetzt werden: sein Wert vor der Änderung wurde nie gelesen.</translation>
    </message>
    <message>
        <source>%1 on module %2</source>
        <translation>%1 an Modul %2</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1 on module %2 (value before unknown)</source>
        <translation>%1 an Modul %2 (Wert vorher unbekannt)</translation>
    </message>
    <message>
        <source>Put back: %1.</source>
        <translation>Zurückgesetzt: %1.</translation>
    </message>
    <message>
        <source>Not put back: %1.</source>
        <translation>Nicht zurückgesetzt: %1.</translation>
    </message>
    <message>
        <source>Reading what the device holds before writing…</source>
        <translation>Vor dem Schreiben wird gelesen, was das Gerät hält…</translation>
    </message>
    <message>
        <source>Nothing written: the device values could not all be read (%1).</source>
        <translation>Nichts geschrieben: die Gerätewerte konnten nicht alle gelesen werden (%1).</translation>
    </message>
    <message>
        <source>Reading the device to compare…</source>
        <translation>Das Gerät wird zum Vergleichen gelesen…</translation>
    </message>
    <message>
        <source>Not compared: the device could not be read (%1).</source>
        <translation>Nicht verglichen: das Gerät konnte nicht gelesen werden (%1).</translation>
    </message>
    <message>
        <source>Disconnected. %1</source>
        <translation>Getrennt. %1</translation>
    </message>
    <message>
        <source>The device warned: %1</source>
        <translation>Das Gerät warnte: %1</translation>
    </message>
</context>
<context>
    <name>vt::app::DeviceStateControl</name>
    <message>
        <source>Module %1 has no writable %2.</source>
        <translation>Modul %1 hat kein schreibbares %2.</translation>
    </message>
    <message>
        <source>A device state write is still running.</source>
        <translation>Ein Schreibvorgang für den Gerätezustand läuft noch.</translation>
    </message>
    <message>
        <source>%1 = %2 written to module %3 (%4).</source>
        <translation>%1 = %2 in Modul %3 geschrieben (%4).</translation>
    </message>
    <message>
        <source>%1 = %2 not written to module %3: %4</source>
        <translation>%1 = %2 nicht in Modul %3 geschrieben: %4</translation>
    </message>
</context>
<context>
    <name>vt::app::FileController</name>
    <message>
        <source>ValveTune</source>
        <translation>ValveTune</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The parameters have unsaved changes. Save them first?</source>
        <translation>Die Parameter enthalten ungespeicherte Änderungen. Zuerst speichern?</translation>
    </message>
    <message>
        <source>New parameter set for %1 with the dictionary&apos;s defaults.</source>
        <translation>Neuer Parametersatz für %1 mit den Vorgabewerten des Wörterbuchs.</translation>
    </message>
    <message>
        <source>Open Parameter File</source>
        <translation>Parameterdatei öffnen</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Save Parameter File</source>
        <translation>Parameterdatei speichern</translation>
    </message>
    <message>
        <source>There are no parameters to save.</source>
        <translation>Es gibt keine Parameter zum Speichern.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV-Dateien (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Exported %1 (separator &apos;;&apos;, decimal comma)</source>
        <translation>%1 exportiert (Trennzeichen &apos;;&apos;, Dezimalkomma)</translation>
    </message>
    <message>
        <source>Exported %1 (separator &apos;,&apos;, decimal point)</source>
        <translation>%1 exportiert (Trennzeichen &apos;,&apos;, Dezimalpunkt)</translation>
    </message>
    <message>
        <source>Compare with File</source>
        <translation>Mit Datei vergleichen</translation>
    </message>
    <message>
        <source>ValveTune parameter files (*.vtpar);;Fold plans (*.vtfold);;All files (*)</source>
        <translation>ValveTune-Parameterdateien (*.vtpar);;Modulpläne (*.vtfold);;Alle Dateien (*)</translation>
    </message>
</context>
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
        <source>Monitor</source>
        <translation>Monitor</translation>
    </message>
    <message>
        <source>Telegrams</source>
        <translation>Telegramme</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Clear List</source>
        <translation>Liste leeren</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Verbinde mit %1…</translation>
    </message>
    <message numerus="yes">
        <source>Connected: %n module(s).</source>
        <translation>
            <numerusform>Verbunden: %n Modul.</numerusform>
            <numerusform>Verbunden: %n Module.</numerusform>
        </translation>
    </message>
    <message>
        <source>Connection failed: %1</source>
        <translation>Verbindung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Disconnected.</source>
        <translation>Getrennt.</translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation>Verbindung verloren: %1</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Export CSV…</source>
        <translation>CSV &amp;exportieren…</translation>
    </message>
    <message>
        <source>Compare with &amp;File…</source>
        <translation>Mit &amp;Datei vergleichen…</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>Wieder&amp;herstellen</translation>
    </message>
    <message>
        <source>Revert to &amp;Device</source>
        <translation>Auf &amp;Gerätewerte zurücksetzen</translation>
    </message>
    <message>
        <source>Revert to &amp;File</source>
        <translation>Auf &amp;Dateiwerte zurücksetzen</translation>
    </message>
    <message>
        <source>Compare with De&amp;vice…</source>
        <translation>Mit &amp;Gerät vergleichen…</translation>
    </message>
    <message>
        <source>&amp;Live Display Values</source>
        <translation>&amp;Live-Anzeigewerte</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Linearisation</source>
        <translation>Linearisierung</translation>
    </message>
    <message>
        <source>%1 on module %2</source>
        <translation>%1 an Modul %2</translation>
    </message>
    <message>
        <source>Could not put back (link gone): %1. Check the axis.</source>
        <translation>Nicht zurückgesetzt (Verbindung weg): %1. Achse prüfen.</translation>
    </message>
    <message>
        <source>The monitor was stopped:</source>
        <translation>Der Monitor wurde angehalten:</translation>
    </message>
    <message>
        <source>Reading the connected node for the fold wizard …</source>
        <translation>Der angeschlossene Knoten wird für den Knoten-Assistenten gelesen …</translation>
    </message>
    <message numerus="yes">
        <source>The fold wizard read %n module(s) of the connected node.</source>
        <translation>
            <numerusform>Der Knoten-Assistent hat %n Modul des angeschlossenen Knotens gelesen.</numerusform>
            <numerusform>Der Knoten-Assistent hat %n Module des angeschlossenen Knotens gelesen.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Undo: %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <source>&amp;Redo: %1</source>
        <translation>Wieder&amp;herstellen: %1</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>Workbench</source>
        <translation>Werkbank</translation>
    </message>
    <message>
        <source>Commissioning Re&amp;port…</source>
        <translation>Inbetriebnahme&amp;protokoll…</translation>
    </message>
    <message>
        <source>Open Session &amp;Log Folder</source>
        <translation>Ordner der Sitzungs&amp;protokolle öffnen</translation>
    </message>
    <message>
        <source>Every write of a session is kept in a log file in this folder.</source>
        <translation>Jeder Schreibvorgang einer Sitzung wird in einer Protokolldatei in diesem Ordner festgehalten.</translation>
    </message>
    <message>
        <source>Session Logs</source>
        <translation>Sitzungsprotokolle</translation>
    </message>
    <message>
        <source>The session logs are kept in %1.</source>
        <translation>Die Sitzungsprotokolle liegen in %1.</translation>
    </message>
</context>
<context>
    <name>vt::app::QuitController</name>
    <message>
        <source>Save, Put Back and Quit</source>
        <translation>Speichern, zurücksetzen und beenden</translation>
    </message>
    <message>
        <source>Save and Quit</source>
        <translation>Speichern und beenden</translation>
    </message>
    <message>
        <source>Put Back, Quit Without Saving</source>
        <translation>Zurücksetzen, ohne Speichern beenden</translation>
    </message>
    <message>
        <source>Put Back and Quit</source>
        <translation>Zurücksetzen und beenden</translation>
    </message>
    <message>
        <source>Quit Without Saving or Putting Back</source>
        <translation>Ohne Speichern und Zurücksetzen beenden</translation>
    </message>
    <message>
        <source>Quit Without Putting Back</source>
        <translation>Ohne Zurücksetzen beenden</translation>
    </message>
    <message>
        <source>Quit Without Saving</source>
        <translation>Ohne Speichern beenden</translation>
    </message>
    <message>
        <source>Stop the Test and Quit</source>
        <translation>Test stoppen und beenden</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>The parameters have unsaved edits. They are lost unless you save them.</source>
        <translation>Die Parameter enthalten ungespeicherte Änderungen. Sie gehen verloren, wenn Sie sie nicht speichern.</translation>
    </message>
    <message>
        <source>The parameters in %1 have unsaved edits. They are lost unless you save them.</source>
        <translation>Die Parameter in %1 enthalten ungespeicherte Änderungen. Sie gehen verloren, wenn Sie sie nicht speichern.</translation>
    </message>
    <message>
        <source>A workbench test is running. It is stopped first and puts back the set value it drives, whatever you choose.</source>
        <translation>Ein Test der Werkbank läuft. Er wird zuerst gestoppt und setzt den Sollwert, den er vorgibt, in jedem Fall zurück.</translation>
    </message>
    <message>
        <source>A set value step of the monitor is being written. ValveTune lets the write end first.</source>
        <translation>Ein Sollwertsprung des Monitors wird gerade geschrieben. ValveTune lässt das Schreiben zuerst zu Ende gehen.</translation>
    </message>
    <message>
        <source>ValveTune changed values that drive the actuator:
%1</source>
        <translation>ValveTune hat Werte geändert, die den Antrieb steuern:
%1</translation>
    </message>
    <message>
        <source>Before ValveTune quits:

%1</source>
        <translation>Bevor ValveTune beendet wird:

%1</translation>
    </message>
    <message>
        <source>Quit ValveTune</source>
        <translation>ValveTune beenden</translation>
    </message>
    <message>
        <source>Not quit: the parameters were not saved.</source>
        <translation>Nicht beendet: Die Parameter wurden nicht gespeichert.</translation>
    </message>
    <message>
        <source>Stopping the workbench test before quitting…</source>
        <translation>Der Test der Werkbank wird vor dem Beenden gestoppt …</translation>
    </message>
</context>
<context>
    <name>vt::app::ReportController</name>
    <message>
        <source>There is nothing to report: connect to a node or open a parameter file first.</source>
        <translation>Es gibt nichts zu protokollieren: zuerst mit einem Knoten verbinden oder eine Parameterdatei öffnen.</translation>
    </message>
</context>
<context>
    <name>vt::app::WelcomePage</name>
    <message>
        <source>Welcome to ValveTune</source>
        <translation>Willkommen bei ValveTune</translation>
    </message>
    <message>
        <source>No device is connected and no parameter file is open. Start with one of these:</source>
        <translation>Kein Gerät ist verbunden und keine Parameterdatei geöffnet. Beginnen Sie mit einem von diesen:</translation>
    </message>
    <message>
        <source>Connect…</source>
        <translation>Verbinden…</translation>
    </message>
    <message>
        <source>Reach a node or module over serial, TCP, CAN or HART.</source>
        <translation>Einen Knoten oder ein Modul über seriell, TCP, CAN oder HART erreichen.</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Öffnen…</translation>
    </message>
    <message>
        <source>Open a parameter file (.vtpar) or a fold plan (.vtfold).</source>
        <translation>Eine Parameterdatei (.vtpar) oder einen Modulplan (.vtfold) öffnen.</translation>
    </message>
    <message>
        <source>New…</source>
        <translation>Neu…</translation>
    </message>
    <message>
        <source>Make a parameter file for a module type and version, without a device.</source>
        <translation>Eine Parameterdatei für einen Modultyp und eine Version anlegen, ohne Gerät.</translation>
    </message>
    <message>
        <source>Try the simulator…</source>
        <translation>Simulator ausprobieren…</translation>
    </message>
    <message>
        <source>Connect to a built-in simulated node: every window works, no valve moves.</source>
        <translation>Mit einem eingebauten simulierten Knoten verbinden: jedes Fenster funktioniert, kein Ventil bewegt sich.</translation>
    </message>
</context>
<context>
    <name>vt::app::Workspace</name>
    <message>
        <source>No module answered on %1.</source>
        <translation>Auf %1 hat kein Modul geantwortet.</translation>
    </message>
</context>
<context>
    <name>vt::link</name>
    <message>
        <source>empty item (two commas in a row?)</source>
        <translation>leerer Eintrag (zwei Kommas hintereinander?)</translation>
    </message>
    <message>
        <source>expected key=value</source>
        <translation>erwartet Schlüssel=Wert</translation>
    </message>
    <message>
        <source>given twice</source>
        <translation>doppelt angegeben</translation>
    </message>
    <message>
        <source>probability must be a number between 0 and 1</source>
        <translation>Wahrscheinlichkeit muss eine Zahl zwischen 0 und 1 sein</translation>
    </message>
    <message>
        <source>delay must be whole milliseconds, 0 to 60000</source>
        <translation>Verzögerung muss ganze Millisekunden sein, 0 bis 60000</translation>
    </message>
    <message>
        <source>cut must be a whole number of frames</source>
        <translation>cut muss eine ganze Anzahl Telegramme sein</translation>
    </message>
    <message>
        <source>seed must be a whole number from 0 to 4294967295</source>
        <translation>seed muss eine ganze Zahl von 0 bis 4294967295 sein</translation>
    </message>
    <message>
        <source>cut and seed apply to both directions; drop the tx./rx. prefix</source>
        <translation>cut und seed gelten für beide Richtungen; das Präfix tx./rx. weglassen</translation>
    </message>
    <message>
        <source>unknown key (known: drop, corrupt, delay, cut, seed; drop, corrupt and delay may take a tx. or rx. prefix)</source>
        <translation>unbekannter Schlüssel (bekannt: drop, corrupt, delay, cut, seed; drop, corrupt und delay erlauben das Präfix tx. oder rx.)</translation>
    </message>
</context>
<context>
    <name>vt::link::CanLink</name>
    <message>
        <source>CAN socket %1 was closed and cannot be reopened</source>
        <translation>CAN-Socket %1 wurde geschlossen und kann nicht wieder geöffnet werden</translation>
    </message>
    <message>
        <source>CAN socket %1 is unusable: %2</source>
        <translation>CAN-Socket %1 ist unbrauchbar: %2</translation>
    </message>
    <message>
        <source>Cannot open CAN interface %1: SocketCAN is not available in this kernel (%2)</source>
        <translation>CAN-Schnittstelle %1 kann nicht geöffnet werden: SocketCAN ist in diesem Kernel nicht verfügbar (%2)</translation>
    </message>
    <message>
        <source>Cannot open CAN interface %1: %2</source>
        <translation>CAN-Schnittstelle %1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>Cannot open CAN interface %1: no such network interface</source>
        <translation>CAN-Schnittstelle %1 kann nicht geöffnet werden: keine solche Netzwerkschnittstelle</translation>
    </message>
    <message>
        <source>CAN interface %1: transmit backlog overflow</source>
        <translation>CAN-Schnittstelle %1: Sendepuffer übergelaufen</translation>
    </message>
    <message>
        <source>CAN interface %1: short write (%2 bytes)</source>
        <translation>CAN-Schnittstelle %1: unvollständig geschrieben (%2 Bytes)</translation>
    </message>
    <message>
        <source>CAN interface %1: transmit queue stays full (bus off?)</source>
        <translation>CAN-Schnittstelle %1: Sendewarteschlange bleibt voll (Bus-off?)</translation>
    </message>
    <message>
        <source>CAN interface %1: write failed: %2</source>
        <translation>CAN-Schnittstelle %1: Schreiben fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>CAN interface %1: read failed: %2</source>
        <translation>CAN-Schnittstelle %1: Lesen fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>CAN interface %1: socket closed</source>
        <translation>CAN-Schnittstelle %1: Socket geschlossen</translation>
    </message>
</context>
<context>
    <name>vt::link::FaultLink</name>
    <message>
        <source>Fault injection cut the link after %1 frames</source>
        <translation>Die Fehlerinjektion hat die Verbindung nach %1 Telegrammen getrennt</translation>
    </message>
</context>
<context>
    <name>vt::link::FaultSpecError</name>
    <message>
        <source>fault spec: %1</source>
        <translation>Fehlerangabe: %1</translation>
    </message>
    <message>
        <source>fault spec item &apos;%1&apos;: %2</source>
        <translation>Fehlerangabe, Eintrag &apos;%1&apos;: %2</translation>
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
    <name>vt::link::SerialWorker</name>
    <message>
        <source>Serial port %1 not found</source>
        <translation>Serielle Schnittstelle %1 nicht gefunden</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>Cannot apply %1 baud %2 to %3: %4</source>
        <translation>%1 Baud %2 kann nicht auf %3 eingestellt werden: %4</translation>
    </message>
    <message>
        <source>Write to %1 failed: %2</source>
        <translation>Schreiben auf %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Write to %1 timed out</source>
        <translation>Schreiben auf %1: Zeitüberschreitung</translation>
    </message>
    <message>
        <source>Read from %1 failed: %2</source>
        <translation>Lesen von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Serial port %1 was disconnected</source>
        <translation>Serielle Schnittstelle %1 wurde getrennt</translation>
    </message>
    <message>
        <source>Cannot open %1: it is not a serial port or terminal.</source>
        <translation>%1 kann nicht geöffnet werden: Es ist weder eine serielle Schnittstelle noch ein Terminal.</translation>
    </message>
    <message>
        <source>Cannot open %1: %2 baud is not a rate the port supports.</source>
        <translation>%1 kann nicht geöffnet werden: %2 Baud unterstützt die Schnittstelle nicht.</translation>
    </message>
    <message>
        <source>Cannot open %1: permission denied. Serial ports are for the members of the group %2: add your user to it with &quot;sudo usermod -aG %2 $USER&quot;, then log out and log in again.</source>
        <translation>%1 kann nicht geöffnet werden: Zugriff verweigert. Serielle Schnittstellen dürfen nur Mitglieder der Gruppe %2 öffnen: Fügen Sie Ihren Benutzer mit „sudo usermod -aG %2 $USER“ hinzu, melden Sie sich dann ab und wieder an.</translation>
    </message>
</context>
<context>
    <name>vt::link::SimLink</name>
    <message>
        <source>No simulator is attached to %1</source>
        <translation>An %1 ist kein Simulator angeschlossen</translation>
    </message>
</context>
<context>
    <name>vt::link::TcpLink</name>
    <message>
        <source>Connection to %1 timed out after %2 ms</source>
        <translation>Verbindung zu %1: Zeitüberschreitung nach %2 ms</translation>
    </message>
    <message>
        <source>Connection to %1 closed by the peer</source>
        <translation>Verbindung zu %1 von der Gegenstelle geschlossen</translation>
    </message>
    <message>
        <source>Connection to %1 failed: %2</source>
        <translation>Verbindung zu %1 fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>vt::model::ActuatorRestore</name>
    <message>
        <source>module %1 is not on the node</source>
        <translation>Modul %1 ist nicht am Knoten</translation>
    </message>
</context>
<context>
    <name>vt::model::BlockTitles</name>
    <message>
        <source>Display values</source>
        <translation>Anzeigewerte</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Regler</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Bus values</source>
        <translation>Buswerte</translation>
    </message>
    <message>
        <source>Linearisation</source>
        <translation>Linearisierung</translation>
    </message>
    <message>
        <source>Ramps</source>
        <translation>Rampen</translation>
    </message>
    <message>
        <source>Reserved (S)</source>
        <translation>Reserviert (S)</translation>
    </message>
    <message>
        <source>PROFIdrive set values</source>
        <translation>PROFIdrive-Sollwerte</translation>
    </message>
    <message>
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Drive actual value conditioning</source>
        <translation>Istwertaufbereitung Antrieb</translation>
    </message>
    <message>
        <source>Drive output processing</source>
        <translation>Ausgangsverarbeitung Antrieb</translation>
    </message>
    <message>
        <source>Drive position control</source>
        <translation>Lageregelung Antrieb</translation>
    </message>
    <message>
        <source>Open loop movement</source>
        <translation>Gesteuerte Bewegung</translation>
    </message>
    <message>
        <source>Velocity control axis</source>
        <translation>Geschwindigkeitsregelung Achse</translation>
    </message>
    <message>
        <source>Spool position control open loop</source>
        <translation>Schieberposition gesteuert</translation>
    </message>
    <message>
        <source>Pressure control</source>
        <translation>Druckregelung</translation>
    </message>
    <message>
        <source>Actual value</source>
        <translation>Istwert</translation>
    </message>
    <message>
        <source>Channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <source>Ramp</source>
        <translation>Rampe</translation>
    </message>
    <message>
        <source>n-point controller</source>
        <translation>n-Punkt-Regler</translation>
    </message>
    <message>
        <source>Command value</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <source>Fixed command values</source>
        <translation>Festsollwerte</translation>
    </message>
    <message>
        <source>Analogue output</source>
        <translation>Analogausgang</translation>
    </message>
    <message>
        <source>Solenoid 1</source>
        <translation>Magnet 1</translation>
    </message>
    <message>
        <source>Solenoid 2</source>
        <translation>Magnet 2</translation>
    </message>
    <message>
        <source>HART</source>
        <translation>HART</translation>
    </message>
</context>
<context>
    <name>vt::model::CompareModel</name>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>This document</source>
        <translation>Dieses Dokument</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>File %1</source>
        <translation>Datei %1</translation>
    </message>
    <message>
        <source>Take other</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>(not set)</source>
        <translation>(nicht gesetzt)</translation>
    </message>
    <message>
        <source>Take values from the device</source>
        <translation>Werte vom Gerät übernehmen</translation>
    </message>
    <message>
        <source>Take values from %1</source>
        <translation>Werte aus %1 übernehmen</translation>
    </message>
</context>
<context>
    <name>vt::model::Connection</name>
    <message>
        <source>a TCP connection needs a host and a port</source>
        <translation>eine TCP-Verbindung braucht Host und Port</translation>
    </message>
    <message>
        <source>CANopen node %1 is not 1..127</source>
        <translation>CANopen-Knoten %1 liegt nicht in 1..127</translation>
    </message>
    <message>
        <source>a CAN connection needs an interface (can0, vcan0 …)</source>
        <translation>eine CAN-Verbindung braucht eine Schnittstelle (can0, vcan0 …)</translation>
    </message>
    <message>
        <source>module address %1 is not 0..255</source>
        <translation>Moduladresse %1 liegt nicht in 0..255</translation>
    </message>
    <message>
        <source>the link closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
    <message>
        <source>simulated %1 ×%2</source>
        <translation>simuliert %1 ×%2</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>%1, %2, module %3</source>
        <translation>%1, %2, Modul %3</translation>
    </message>
    <message>
        <source>%1, %2, modules %3</source>
        <translation>%1, %2, Module %3</translation>
    </message>
    <message>
        <source>%1 [fault %2]</source>
        <translation>%1 [Fehlerinjektion %2]</translation>
    </message>
</context>
<context>
    <name>vt::model::CurveBinding</name>
    <message>
        <source>module %1 linearisation curve</source>
        <translation>Modul %1 Linearisierungskennlinie</translation>
    </message>
</context>
<context>
    <name>vt::model::DeviceAccess</name>
    <message>
        <source>not readable over %1</source>
        <translation>über %1 nicht lesbar</translation>
    </message>
    <message>
        <source>the module did not identify itself</source>
        <translation>das Modul hat sich nicht zu erkennen gegeben</translation>
    </message>
</context>
<context>
    <name>vt::model::FieldTreeModel</name>
    <message>
        <source>Field</source>
        <translation>Feld</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
</context>
<context>
    <name>vt::model::FoldApply</name>
    <message>
        <source>The address changes cannot be ordered: two modules would need the same address.</source>
        <translation>Die Adressänderungen lassen sich nicht ordnen: Zwei Module bräuchten dieselbe Adresse.</translation>
    </message>
    <message>
        <source>Address not changed.</source>
        <translation>Adresse nicht geändert.</translation>
    </message>
    <message>
        <source>Module %1: identifying at address %2 …</source>
        <translation>Modul %1: Identifizierung an Adresse %2 …</translation>
    </message>
    <message>
        <source>Module %1: no module answers at address %2 (%3).</source>
        <translation>Modul %1: An Adresse %2 antwortet kein Modul (%3).</translation>
    </message>
    <message>
        <source>Software V%1 found, the plan says V%2.</source>
        <translation>Software V%1 gefunden, der Plan sieht V%2 vor.</translation>
    </message>
    <message>
        <source>Mode %1 found, the plan says mode %2.</source>
        <translation>Modus %1 gefunden, der Plan sieht Modus %2 vor.</translation>
    </message>
    <message>
        <source>%1 does not exist on this module&apos;s software; not written.</source>
        <translation>%1 gibt es in der Software dieses Moduls nicht; nicht geschrieben.</translation>
    </message>
    <message>
        <source>Module %1: writing %2 option(s) …</source>
        <translation>Modul %1: %2 Option(en) werden geschrieben …</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Module %1 answers at address %2: set its rotary switch to %3.</source>
        <translation>Modul %1 antwortet an Adresse %2: Stellen Sie seinen Drehschalter auf %3.</translation>
    </message>
    <message>
        <source>Module %1: address %2 → %3 …</source>
        <translation>Modul %1: Adresse %2 → %3 …</translation>
    </message>
    <message>
        <source>Module %1: E22 not written (%2).</source>
        <translation>Modul %1: E22 nicht geschrieben (%2).</translation>
    </message>
    <message>
        <source>no answer with E22 = %1 at address %1</source>
        <translation>keine Antwort mit E22 = %1 an Adresse %1</translation>
    </message>
    <message>
        <source>Module %1: %2.</source>
        <translation>Modul %1: %2.</translation>
    </message>
    <message>
        <source>Scan: identifying address %1 …</source>
        <translation>Abfrage: Identifizierung von Adresse %1 …</translation>
    </message>
    <message>
        <source>Scan: no module answers at address %1.</source>
        <translation>Abfrage: An Adresse %1 antwortet kein Modul.</translation>
    </message>
    <message>
        <source>Scan: address %1 answers as %2, expected %3.</source>
        <translation>Abfrage: Adresse %1 antwortet als %2, erwartet %3.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>Every module is configured and answers at its address.</source>
        <translation>Alle Module sind konfiguriert und antworten an ihrer Adresse.</translation>
    </message>
    <message>
        <source>The node is not configured as planned; see the modules&apos; notes.</source>
        <translation>Der Knoten ist nicht wie geplant konfiguriert; siehe die Hinweise zu den Modulen.</translation>
    </message>
</context>
<context>
    <name>vt::model::FoldCheck</name>
    <message>
        <source>The plan has no modules.</source>
        <translation>Der Plan enthält keine Module.</translation>
    </message>
    <message>
        <source>%1 modules: an OPAT node has the master and at most 7 CAN slaves (rotary switch 1 … 7; OPAT manual §1.4).</source>
        <translation>%1 Module: Ein OPAT-Knoten hat den Master und höchstens 7 CAN-Slaves (Drehschalter 1 … 7; OPAT-Handbuch §1.4).</translation>
    </message>
    <message>
        <source>%1 modules: a DMA node addresses at most 32 modules (E22 = 1 … 32; DMA Profibus Anleitung §1.5, DMA Profinet manual §1.5).</source>
        <translation>%1 Module: Ein DMA-Knoten adressiert höchstens 32 Module (E22 = 1 … 32; DMA Profibus Anleitung §1.5, DMA-Profinet-Handbuch §1.5).</translation>
    </message>
    <message>
        <source>%1 DMA modules: CMD 15 reaches E22 = 1 … 5 only. Modules above 5 can be reached by CMD 3 / CMD 6 only and cannot be part of the cyclic PLC image (DMA Profibus Anleitung §1.5, DMA Profinet manual §1.5). Plan at most 5 modules for CMD 15.</source>
        <translation>%1 DMA-Module: CMD 15 erreicht nur E22 = 1 … 5. Module über 5 sind nur mit CMD 3 / CMD 6 erreichbar und können nicht Teil des zyklischen SPS-Abbilds sein (DMA Profibus Anleitung §1.5, DMA-Profinet-Handbuch §1.5). Für CMD 15 höchstens 5 Module planen.</translation>
    </message>
    <message>
        <source>The product number &quot;%1&quot; does not decide the GSD file: HCS0220.GSD is assumed. Product numbers 5 xxx xxx x1 … x4 use hcs0220.gsd, 5 005 xxx x5 use hcs0ea7.gsd (DMA Profibus Anleitung §6.1.1).</source>
        <translation>Die Produktnummer &quot;%1&quot; legt die GSD-Datei nicht fest: HCS0220.GSD wird angenommen. Produktnummern 5 xxx xxx x1 … x4 verwenden hcs0220.gsd, 5 005 xxx x5 verwenden hcs0ea7.gsd (DMA Profibus Anleitung §6.1.1).</translation>
    </message>
    <message>
        <source>No product number given: HCS0220.GSD is assumed. Product numbers 5 xxx xxx x1 … x4 use hcs0220.gsd, 5 005 xxx x5 use hcs0ea7.gsd (DMA Profibus Anleitung §6.1.1).</source>
        <translation>Keine Produktnummer angegeben: HCS0220.GSD wird angenommen. Produktnummern 5 xxx xxx x1 … x4 verwenden hcs0220.gsd, 5 005 xxx x5 verwenden hcs0ea7.gsd (DMA Profibus Anleitung §6.1.1).</translation>
    </message>
    <message>
        <source>The first module (the one with the PROFIBUS interface) must always have SADR = 0 (OPAT manual §1.4).</source>
        <translation>Das erste Modul (das mit der PROFIBUS-Schnittstelle) muss immer SADR = 0 haben (OPAT-Handbuch §1.4).</translation>
    </message>
    <message>
        <source>Module %1 (%2): CAN slaves take rotary switch positions 1 … 7 only (OPAT manual §1.4, §3.1).</source>
        <translation>Modul %1 (%2): CAN-Slaves haben nur die Drehschalterstellungen 1 … 7 (OPAT-Handbuch §1.4, §3.1).</translation>
    </message>
    <message>
        <source>Module %1 (%2): E22 = 0 switches the module&apos;s bus function off; the node cannot reach it.</source>
        <translation>Modul %1 (%2): E22 = 0 schaltet die Busfunktion des Moduls ab; der Knoten erreicht es nicht.</translation>
    </message>
    <message>
        <source>Module %1 (%2): E22 must be 1 … 32.</source>
        <translation>Modul %1 (%2): E22 muss 1 … 32 sein.</translation>
    </message>
    <message>
        <source>Module %1 (%2): CMD 15 reaches E22 = 1 … 5 only; this module is reachable by CMD 3 / CMD 6 only (DMA Profibus Anleitung §1.5, DMA Profinet manual §1.5).</source>
        <translation>Modul %1 (%2): CMD 15 erreicht nur E22 = 1 … 5; dieses Modul ist nur mit CMD 3 / CMD 6 erreichbar (DMA Profibus Anleitung §1.5, DMA-Profinet-Handbuch §1.5).</translation>
    </message>
    <message>
        <source>Modules %1 share SADR %2: the red LED lights and the master reports exception 12 &quot;two or more slaves have the same slave address&quot; (OPAT manual §1.3.2, §3.3). Set a different rotary switch position.</source>
        <translation>Module %1 haben dieselbe SADR %2: Die rote LED leuchtet und der Master meldet Exception 12 &quot;zwei oder mehr Slaves haben dieselbe Adresse&quot; (OPAT-Handbuch §1.3.2, §3.3). Anderen Drehschalter-Wert einstellen.</translation>
    </message>
    <message>
        <source>Modules %1 share E22 = %2: the node cannot tell them apart. Set E22 = 1 … n from left to right (DMA Profibus Anleitung §1.3, DMA Profinet manual §1.3).</source>
        <translation>Module %1 haben dasselbe E22 = %2: Der Knoten kann sie nicht unterscheiden. E22 = 1 … n von links nach rechts setzen (DMA Profibus Anleitung §1.3, DMA-Profinet-Handbuch §1.3).</translation>
    </message>
    <message>
        <source>With %1 modules CMD 15 addresses %2 … %3; a module outside that range gets no set values and the node answers exception 8 &quot;timeout slave, address wrong or not installed&quot; (OPAT manual §3.3, DMA Profinet manual §4.3).</source>
        <translation>Mit %1 Modulen adressiert CMD 15 %2 … %3; ein Modul außerhalb erhält keine Sollwerte und der Knoten antwortet mit Exception 8 &quot;Timeout Slave, Adresse falsch oder nicht installiert&quot; (OPAT-Handbuch §3.3, DMA-Profinet-Handbuch §4.3).</translation>
    </message>
    <message>
        <source>Set the slaves&apos; rotary switches in rising, consecutive order beginning with 1 (OPAT manual §1.6).</source>
        <translation>Die Drehschalter der Slaves aufsteigend und lückenlos ab 1 einstellen (OPAT-Handbuch §1.6).</translation>
    </message>
    <message>
        <source>Set E22 = 1 for the module on the left, rising towards the node module (DMA Profibus Anleitung §1.3, DMA Profinet manual §1.3, §4.1).</source>
        <translation>E22 = 1 für das linke Modul setzen, aufsteigend zum Knotenmodul hin (DMA Profibus Anleitung §1.3, DMA-Profinet-Handbuch §1.3, §4.1).</translation>
    </message>
    <message>
        <source>The PLC sends SNUM = %1 but the node has %2 modules (master + %3 slaves → SNUM = %3).</source>
        <translation>Die SPS sendet SNUM = %1, der Knoten hat aber %2 Module (Master + %3 Slaves → SNUM = %3).</translation>
    </message>
    <message>
        <source>The PLC sends SNUM = %1 but the node has %2 modules (SNUM = %3).</source>
        <translation>Die SPS sendet SNUM = %1, der Knoten hat aber %2 Module (SNUM = %3).</translation>
    </message>
    <message>
        <source>An SNUM outside %1 is answered with exception 7 &quot;invalid number of connected slaves&quot;.</source>
        <translation>Eine SNUM außerhalb %1 wird mit Exception 7 &quot;ungültige Anzahl angeschlossener Slaves&quot; beantwortet.</translation>
    </message>
    <message>
        <source>The node then waits for modules that are not installed: exception 8 &quot;timeout slave, address wrong or not installed&quot;.</source>
        <translation>Der Knoten wartet dann auf nicht installierte Module: Exception 8 &quot;Timeout Slave, Adresse falsch oder nicht installiert&quot;.</translation>
    </message>
    <message>
        <source>The modules beyond SNUM get no set values and never answer.</source>
        <translation>Die Module jenseits von SNUM erhalten keine Sollwerte und antworten nie.</translation>
    </message>
    <message>
        <source>SNUM also fixes the telegram length (3 + 5 bytes per module, up to %1); a GSD module that is too short gives exception 9 (OPAT manual §3.1, §3.3; DMA Profinet manual §4.1).</source>
        <translation>SNUM legt auch die Telegrammlänge fest (3 + 5 Byte je Modul, bis %1); ein zu kurzes GSD-Modul ergibt Exception 9 (OPAT-Handbuch §3.1, §3.3; DMA-Profinet-Handbuch §4.1).</translation>
    </message>
    <message>
        <source>Module %1 (%2): software version not known; the layout of the manuals&apos; worked examples is assumed. Scan the node to fill it in.</source>
        <translation>Modul %1 (%2): Softwareversion unbekannt; das Layout der Beispiele der Handbücher wird angenommen. Den Knoten scannen, um sie einzutragen.</translation>
    </message>
    <message>
        <source>Module %1 (%2): software V%3 does not belong here; the manual describes %4 for this position.</source>
        <translation>Modul %1 (%2): Software V%3 gehört nicht hierher; das Handbuch beschreibt %4 für diese Position.</translation>
    </message>
    <message>
        <source>Module %1 (%2): the manuals define no CMD 15 layout for software V%3 in mode %4.</source>
        <translation>Modul %1 (%2): Die Handbücher definieren kein CMD-15-Layout für Software V%3 im Modus %4.</translation>
    </message>
    <message>
        <source>The modules run in different modes or software versions. Only the control-byte and status-word bits of each module&apos;s own mode apply; the PLC must read VALUE1/VALUE2 per SADR with that module&apos;s meaning (DMA Profibus Anleitung §6, DMA Profinet manual §5).</source>
        <translation>Die Module arbeiten in verschiedenen Modi oder Softwareversionen. Nur die Bits im Steuerbyte und Statuswort entsprechend dem Modus des jeweiligen Moduls sind zu beachten; die SPS muss VALUE1/VALUE2 je SADR mit der Bedeutung dieses Moduls lesen (DMA Profibus Anleitung §6, DMA-Profinet-Handbuch §5).</translation>
    </message>
    <message>
        <source>Module %1 (%2): %3 is not a bus option of this module here; it is ignored.</source>
        <translation>Modul %1 (%2): %3 ist hier keine Busoption dieses Moduls; wird ignoriert.</translation>
    </message>
    <message>
        <source>Module %1 (%2): %3 does not exist in software V%4; it is ignored.</source>
        <translation>Modul %1 (%2): %3 gibt es in Software V%4 nicht; wird ignoriert.</translation>
    </message>
    <message>
        <source>Module %1 (%2): %3 = %4 is outside %5 … %6 (%7).</source>
        <translation>Modul %1 (%2): %3 = %4 liegt außerhalb %5 … %6 (%7).</translation>
    </message>
    <message>
        <source>E24 = 126: the PROFIBUS master sets the address. Set it before power-up; the address the master assigns then shows in E24 (OPAT manual §1.4).</source>
        <translation>E24 = 126: Der PROFIBUS-Master vergibt die Adresse. Vor dem Einschalten setzen; die vom Master vergebene Adresse erscheint danach in E24 (OPAT-Handbuch §1.4).</translation>
    </message>
    <message>
        <source>E24 = %1: the new PROFIBUS address becomes active only after a power-down/power-up sequence (OPAT manual §1.4).</source>
        <translation>E24 = %1: Die neue PROFIBUS-Adresse wird erst nach Aus- und Wiedereinschalten aktiv (OPAT-Handbuch §1.4).</translation>
    </message>
    <message>
        <source>E28 = 0: a lost CAN slave gives error 7 and the master goes to the disabled state (OPAT manual §5.7).</source>
        <translation>E28 = 0: Ein ausgefallener CAN-Slave ergibt Fehler 7 und der Master geht in den Zustand gesperrt (OPAT-Handbuch §5.7).</translation>
    </message>
    <message>
        <source>E28 = 1: a lost CAN slave sets the error bit, but the master remains in its previous state (OPAT manual §5.7).</source>
        <translation>E28 = 1: Ein ausgefallener CAN-Slave setzt das Fehlerbit, der Master bleibt aber in seinem bisherigen Zustand (OPAT-Handbuch §5.7).</translation>
    </message>
    <message>
        <source>E28 = 2: error 7 is ignored; the master ignores lost CAN slaves, so a lost slave goes unnoticed by the PLC (OPAT manual §5.7).</source>
        <translation>E28 = 2: Fehler 7 wird ignoriert; der Master ignoriert ausgefallene CAN-Slaves, die SPS bemerkt einen Ausfall also nicht (OPAT-Handbuch §5.7).</translation>
    </message>
    <message>
        <source>Module %1 (%2): E23 = 0 switches the bus telegram timeout off; the module does not react when the PLC stops sending.</source>
        <translation>Modul %1 (%2): E23 = 0 schaltet die Bus-Telegrammüberwachung ab; das Modul reagiert nicht, wenn die SPS keine Telegramme mehr sendet.</translation>
    </message>
    <message>
        <source>Module %1 (%2): E17 = 0 keeps the analogue set value input active; set E17 = 2 when the set value comes from the bus only.</source>
        <translation>Modul %1 (%2): E17 = 0 lässt den analogen Sollwerteingang aktiv; E17 = 2 setzen, wenn der Sollwert nur über den Bus kommt.</translation>
    </message>
    <message>
        <source>Module %1 (%2): E26 = 0 disables CAN; the master cannot reach the slaves (OPAT manual §7).</source>
        <translation>Modul %1 (%2): E26 = 0 sperrt CAN; der Master erreicht die Slaves nicht (OPAT-Handbuch §7).</translation>
    </message>
    <message>
        <source>The modules are given different CAN baud rates (E26): master and slaves must use the same rate or the master loses its slaves (error 7, exception 5 &quot;timeout (CAN connection)&quot;).</source>
        <translation>Die Module haben verschiedene CAN-Baudraten (E26): Master und Slaves müssen dieselbe Rate verwenden, sonst verliert der Master seine Slaves (Fehler 7, Exception 5 &quot;Timeout (CAN-Verbindung)&quot;).</translation>
    </message>
    <message>
        <source>A CAN baud rate (E26) changed through PROFIBUS becomes active only after a reboot (OPAT manual §7).</source>
        <translation>Eine über PROFIBUS geänderte CAN-Baudrate (E26) wird erst nach einem Neustart aktiv (OPAT-Handbuch §7).</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Module %1 (address %2) is planned as V%3 in mode %4, but the connected node&apos;s module at that address runs V%5 in mode %6. The plan&apos;s options and the PLC image would not fit it; scan the node or change the plan.</source>
        <translation>Modul %1 (Adresse %2) ist als V%3 in Modus %4 geplant, aber das Modul des angeschlossenen Knotens an dieser Adresse läuft mit V%5 in Modus %6. Die Optionen des Plans und das SPS-Abbild passen nicht dazu; scannen Sie den Knoten oder ändern Sie den Plan.</translation>
    </message>
    <message>
        <source>Module %1 (address %2) is planned, but no module of the connected node answers at that address.</source>
        <translation>Modul %1 (Adresse %2) ist geplant, aber an dieser Adresse antwortet kein Modul des angeschlossenen Knotens.</translation>
    </message>
    <message>
        <source>The connected node has a module at address %1 (V%2, mode %3) that the plan does not contain.</source>
        <translation>Der angeschlossene Knoten hat an Adresse %1 ein Modul (V%2, Modus %3), das der Plan nicht enthält.</translation>
    </message>
</context>
<context>
    <name>vt::model::FoldPlan</name>
    <message>
        <source>OPAT PROFIBUS master with CAN slaves</source>
        <translation>OPAT-PROFIBUS-Master mit CAN-Slaves</translation>
    </message>
    <message>
        <source>DMA-2 modules on a PROFIBUS node</source>
        <translation>DMA-2-Module an einem PROFIBUS-Knoten</translation>
    </message>
    <message>
        <source>DMA-2 modules on a PROFINET node</source>
        <translation>DMA-2-Module an einem PROFINET-Knoten</translation>
    </message>
    <message>
        <source>E22 = %1</source>
        <translation>E22 = %1</translation>
    </message>
    <message>
        <source>SADR 0 (master)</source>
        <translation>SADR 0 (Master)</translation>
    </message>
    <message>
        <source>SADR %1 (rotary switch %1)</source>
        <translation>SADR %1 (Drehschalter %1)</translation>
    </message>
</context>
<context>
    <name>vt::model::FoldPlanFile</name>
    <message>
        <source>The fold plan file is damaged: %1 is not a whole number.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1 ist keine ganze Zahl.</translation>
    </message>
    <message>
        <source>The fold plan file is damaged: %1 is outside %2 … %3.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1 liegt außerhalb %2 … %3.</translation>
    </message>
    <message>
        <source>The fold plan file is damaged: %1 is not a text.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1 ist kein Text.</translation>
    </message>
    <message>
        <source>The fold plan file is damaged: %1 is longer than %2 bytes.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1 ist länger als %2 Byte.</translation>
    </message>
    <message>
        <source>The fold plan file is damaged: %1 is not opat, dma-pb or dma-pn.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1 ist nicht opat, dma-pb oder dma-pn.</translation>
    </message>
    <message>
        <source>The fold plan file is damaged: %1 is not a list.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1 ist keine Liste.</translation>
    </message>
    <message>
        <source>The fold plan file is damaged: %1 has more than %2 entries.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1 hat mehr als %2 Einträge.</translation>
    </message>
    <message>
        <source>The fold plan file is damaged: %1 is not an object.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1 ist kein Objekt.</translation>
    </message>
    <message>
        <source>The fold plan file is damaged: %1.</source>
        <translation>Die Modulplan-Datei ist beschädigt: %1.</translation>
    </message>
    <message>
        <source>The file is larger than %1 KiB; it is not a fold plan.</source>
        <translation>Die Datei ist größer als %1 KiB; sie ist kein Modulplan.</translation>
    </message>
    <message>
        <source>The file is not valid JSON (a number is out of range).</source>
        <translation>Die Datei ist kein gültiges JSON (eine Zahl liegt außerhalb des Bereichs).</translation>
    </message>
    <message>
        <source>The file is not valid JSON (byte %1).</source>
        <translation>Die Datei ist kein gültiges JSON (Byte %1).</translation>
    </message>
    <message>
        <source>The file is nested too deeply to be a fold plan.</source>
        <translation>Die Datei ist zu tief verschachtelt für einen Modulplan.</translation>
    </message>
    <message>
        <source>The file is not a ValveTune fold plan.</source>
        <translation>Die Datei ist kein ValveTune-Modulplan.</translation>
    </message>
    <message>
        <source>The fold plan was written by a newer ValveTune (format version %1); this version reads format %2.</source>
        <translation>Der Modulplan wurde von einem neueren ValveTune geschrieben (Formatversion %1); diese Version liest Format %2.</translation>
    </message>
    <message>
        <source>The fold plan file is incomplete: %1 is missing.</source>
        <translation>Die Modulplan-Datei ist unvollständig: %1 fehlt.</translation>
    </message>
    <message>
        <source>The fold plan file cannot be written: %1</source>
        <translation>Die Modulplan-Datei kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>The fold plan file cannot be read: %1</source>
        <translation>Die Modulplan-Datei kann nicht gelesen werden: %1</translation>
    </message>
</context>
<context>
    <name>vt::model::FoldSheetHtml</name>
    <message>
        <source>PLC configuration</source>
        <translation>SPS-Konfiguration</translation>
    </message>
    <message>
        <source>PLC configuration of the fold</source>
        <translation>SPS-Konfiguration des Knotens</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Modules</source>
        <translation>Module</translation>
    </message>
    <message>
        <source>Product number</source>
        <translation>Produktnummer</translation>
    </message>
    <message>
        <source>GSD file</source>
        <translation>GSD-Datei</translation>
    </message>
    <message>
        <source>Catalogue device</source>
        <translation>Katalog-Gerät</translation>
    </message>
    <message>
        <source>GSD module</source>
        <translation>GSD-Modul</translation>
    </message>
    <message>
        <source>Output (PLC → node)</source>
        <translation>Ausgang (SPS → Knoten)</translation>
    </message>
    <message>
        <source>%1 bytes, SNUM = %2</source>
        <translation>%1 Byte, SNUM = %2</translation>
    </message>
    <message>
        <source>Input (node → PLC)</source>
        <translation>Eingang (Knoten → SPS)</translation>
    </message>
    <message>
        <source>%1 bytes, one module per answer</source>
        <translation>%1 Byte, ein Modul je Antwort</translation>
    </message>
    <message>
        <source>Reserved by the GSD module</source>
        <translation>Vom GSD-Modul reserviert</translation>
    </message>
    <message>
        <source>%1 bytes out / %2 bytes in</source>
        <translation>%1 Byte aus / %2 Byte ein</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Modules and addresses</source>
        <translation>Module und Adressen</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Software / mode</source>
        <translation>Software / Modus</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Options</source>
        <translation>Optionen</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source>Byte</source>
        <translation>Byte</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>Feld</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>Output image (PLC → node, CMD 15 request)</source>
        <translation>Ausgangsabbild (SPS → Knoten, CMD-15-Anfrage)</translation>
    </message>
    <message>
        <source>Input image (node → PLC, multiplexed: SADR names the module)</source>
        <translation>Eingangsabbild (Knoten → SPS, gemultiplext: SADR nennt das Modul)</translation>
    </message>
    <message>
        <source>Bits per module</source>
        <translation>Bits je Modul</translation>
    </message>
    <message>
        <source>Only the bits of each module&apos;s own mode apply (DMA Profibus Anleitung §6, DMA Profinet manual §5).</source>
        <translation>Nur die Bits entsprechend dem Modus des jeweiligen Moduls gelten (DMA Profibus Anleitung §6, DMA-Profinet-Handbuch §5).</translation>
    </message>
    <message>
        <source>Module / SADR</source>
        <translation>Modul / SADR</translation>
    </message>
    <message>
        <source>Layout</source>
        <translation>Layout</translation>
    </message>
    <message>
        <source>Control byte</source>
        <translation>Steuerbyte</translation>
    </message>
    <message>
        <source>Status high byte</source>
        <translation>Status High-Byte</translation>
    </message>
    <message>
        <source>Status low byte</source>
        <translation>Status Low-Byte</translation>
    </message>
    <message>
        <source>Example CMD 15 telegram</source>
        <translation>Beispiel CMD-15-Telegramm</translation>
    </message>
    <message>
        <source>TADR 0x01, control byte 0x00, VALUE1 = 1000 (1.000 V), VALUE2 = 0 for every module.</source>
        <translation>TADR 0x01, Steuerbyte 0x00, VALUE1 = 1000 (1,000 V), VALUE2 = 0 für jedes Modul.</translation>
    </message>
    <message>
        <source>Sources</source>
        <translation>Quellen</translation>
    </message>
</context>
<context>
    <name>vt::model::FoldSheetText</name>
    <message numerus="yes">
        <source>Fold plan: %1 (%2), %n module(s)</source>
        <translation>
            <numerusform>Modulplan: %1 (%2), %n Modul</numerusform>
            <numerusform>Modulplan: %1 (%2), %n Module</numerusform>
        </translation>
    </message>
    <message>
        <source>Title:</source>
        <translation>Titel:</translation>
    </message>
    <message>
        <source>GSD file:</source>
        <translation>GSD-Datei:</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Gerät:</translation>
    </message>
    <message>
        <source>GSD module:</source>
        <translation>GSD-Modul:</translation>
    </message>
    <message>
        <source>Output:</source>
        <translation>Ausgang:</translation>
    </message>
    <message>
        <source>%1 bytes (PLC to node, CMD 15 request, SNUM = %2)</source>
        <translation>%1 Byte (SPS zum Knoten, CMD-15-Anfrage, SNUM = %2)</translation>
    </message>
    <message>
        <source>Input:</source>
        <translation>Eingang:</translation>
    </message>
    <message>
        <source>%1 bytes (node to PLC, one module per answer)</source>
        <translation>%1 Byte (Knoten zur SPS, ein Modul je Antwort)</translation>
    </message>
    <message>
        <source>Reserved:</source>
        <translation>Reserviert:</translation>
    </message>
    <message>
        <source>%1 / %2 bytes out / in by the GSD module</source>
        <translation>%1 / %2 Byte aus / ein durch das GSD-Modul</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation>Quelle:</translation>
    </message>
    <message>
        <source>Output image (PLC to node)</source>
        <translation>Ausgangsabbild (SPS zum Knoten)</translation>
    </message>
    <message>
        <source>byte</source>
        <translation>Byte</translation>
    </message>
    <message>
        <source>field</source>
        <translation>Feld</translation>
    </message>
    <message>
        <source>meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>Module %1 (%2): %3, output bytes %4..%5</source>
        <translation>Modul %1 (%2): %3, Ausgangsbytes %4..%5</translation>
    </message>
    <message>
        <source>Module %1: %2, output bytes %3..%4</source>
        <translation>Modul %1: %2, Ausgangsbytes %3..%4</translation>
    </message>
    <message>
        <source>answer with SADR = %1: VALUE1 = %2; VALUE2 = %3</source>
        <translation>Antwort mit SADR = %1: VALUE1 = %2; VALUE2 = %3</translation>
    </message>
    <message>
        <source>control byte bits: %1</source>
        <translation>Steuerbyte-Bits: %1</translation>
    </message>
    <message>
        <source>status high byte: %1</source>
        <translation>Status High-Byte: %1</translation>
    </message>
    <message>
        <source>status low byte: %1</source>
        <translation>Status Low-Byte: %1</translation>
    </message>
    <message>
        <source>no signals in this mode (error number while ERROR is set)</source>
        <translation>keine Signale in diesem Modus (Fehlernummer solange ERROR gesetzt ist)</translation>
    </message>
    <message>
        <source>%1 (error number while ERROR is set)</source>
        <translation>%1 (Fehlernummer solange ERROR gesetzt ist)</translation>
    </message>
    <message>
        <source>Input image (node to PLC, multiplexed: SADR names the module)</source>
        <translation>Eingangsabbild (Knoten zur SPS, gemultiplext: SADR nennt das Modul)</translation>
    </message>
    <message>
        <source>Example CMD 15 telegram (TADR 0x01, control byte 0x00, VALUE1 = 1000 = 1.000 V, VALUE2 = 0 for every module):</source>
        <translation>Beispiel CMD-15-Telegramm (TADR 0x01, Steuerbyte 0x00, VALUE1 = 1000 = 1,000 V, VALUE2 = 0 für jedes Modul):</translation>
    </message>
</context>
<context>
    <name>vt::model::GuidedTuning</name>
    <message>
        <source>Choose a module and a set value first.</source>
        <translation>Zuerst ein Modul und einen Sollwert wählen.</translation>
    </message>
    <message>
        <source>The dictionary names no P gain for %1: there is nothing to tune.</source>
        <translation>Das Wörterbuch nennt für %1 keinen P-Anteil: Es gibt nichts einzustellen.</translation>
    </message>
    <message>
        <source>The dictionary names no response for %1: there is no overshoot to measure.</source>
        <translation>Das Wörterbuch nennt für %1 keine Antwort: Es gibt kein Überschwingen zu messen.</translation>
    </message>
    <message>
        <source>The guided change measures an up step: From below To, with a hold time.</source>
        <translation>Die geführte Änderung misst einen Sprung nach oben: Von kleiner als Bis, mit einer Haltezeit.</translation>
    </message>
    <message>
        <source>The overshoot limit must be more than 0 %.</source>
        <translation>Die Grenze für das Überschwingen muss größer als 0 % sein.</translation>
    </message>
    <message>
        <source>Allow at least one iteration.</source>
        <translation>Mindestens einen Durchgang zulassen.</translation>
    </message>
    <message>
        <source>Reading the gains failed: %1</source>
        <translation>Lesen der Verstärkungen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>Aborted before anything was written.</source>
        <translation>Abgebrochen, bevor etwas geschrieben wurde.</translation>
    </message>
    <message>
        <source>The step cannot be run.</source>
        <translation>Der Sprung kann nicht ausgeführt werden.</translation>
    </message>
    <message>
        <source>Aborted.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>The step test ended early: %1</source>
        <translation>Der Sprungtest endete vorzeitig: %1</translation>
    </message>
    <message>
        <source>Iteration %1: %2 rang past the set value and did not settle within the hold.</source>
        <translation>Durchgang %1: Mit %2 schwang die Antwort über den Sollwert und kam innerhalb der Haltezeit nicht zur Ruhe.</translation>
    </message>
    <message>
        <source>no step</source>
        <translation>kein Sprung</translation>
    </message>
    <message>
        <source>The step at %1 gave no figures (%2): hold it longer.</source>
        <translation>Der Sprung mit %1 ergab keine Kennwerte (%2): Haltezeit verlängern.</translation>
    </message>
    <message>
        <source>Iteration %1: %2 gave %3 % overshoot.</source>
        <translation>Durchgang %1: %2 ergab %3 % Überschwingen.</translation>
    </message>
    <message>
        <source>Next: %1.</source>
        <translation>Als Nächstes: %1.</translation>
    </message>
    <message>
        <source>The gains could not be written.</source>
        <translation>Die Verstärkungen konnten nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Target reached with %1: Keep leaves these gains on the device, Abort puts back %2.</source>
        <translation>Ziel erreicht mit %1: Übernehmen lässt diese Verstärkungen im Gerät, Abbrechen stellt %2 wieder her.</translation>
    </message>
    <message>
        <source>No gain within the limit was found in the iterations allowed.</source>
        <translation>In den zugelassenen Durchgängen wurde keine Verstärkung innerhalb der Grenze gefunden.</translation>
    </message>
    <message>
        <source>The iterations ran out; the best within the limit is %1: Keep or Abort.</source>
        <translation>Die Durchgänge sind aufgebraucht; die beste Einstellung innerhalb der Grenze ist %1: Übernehmen oder Abbrechen.</translation>
    </message>
    <message>
        <source>Even the lowest gain overshoots more than the limit; the I portion or the ramps need a look.</source>
        <translation>Selbst die kleinste Verstärkung schwingt weiter über als erlaubt; I-Anteil oder Rampen prüfen.</translation>
    </message>
    <message>
        <source>Module %1: write %2?</source>
        <translation>Modul %1: %2 schreiben?</translation>
    </message>
    <message>
        <source>The change was refused; nothing was written. The device holds %1.</source>
        <translation>Die Änderung wurde abgelehnt; nichts wurde geschrieben. Im Gerät steht %1.</translation>
    </message>
    <message>
        <source>Keep or Abort.</source>
        <translation>Übernehmen oder Abbrechen.</translation>
    </message>
    <message>
        <source>Kept %1.</source>
        <translation>Übernommen: %1.</translation>
    </message>
    <message>
        <source>Keep %1.</source>
        <translation>%1 übernehmen.</translation>
    </message>
    <message>
        <source>The kept gains could not be written.</source>
        <translation>Die übernommenen Verstärkungen konnten nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>The original gains are back: %1.</source>
        <translation>Die ursprünglichen Verstärkungen sind wiederhergestellt: %1.</translation>
    </message>
    <message>
        <source>The original gains are NOT back (%1): check the module.</source>
        <translation>Die ursprünglichen Verstärkungen sind NICHT wiederhergestellt (%1): Modul prüfen.</translation>
    </message>
    <message>
        <source>The step at %1 did not move the response (%2): check the feedback and the controller.</source>
        <translation>Der Sprung mit %1 hat die Antwort nicht bewegt (%2): Rückführung und Regler prüfen.</translation>
    </message>
</context>
<context>
    <name>vt::model::IdentityTexts</name>
    <message>
        <source>%1-%2-%3</source>
        <translation>%3.%2.%1</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
</context>
<context>
    <name>vt::model::LCurve</name>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 ist schreibgeschützt</translation>
    </message>
    <message>
        <source>%1 is not active on this device</source>
        <translation>%1 ist in diesem Gerät nicht aktiv</translation>
    </message>
    <message>
        <source>%1 is fixed by the device at %2</source>
        <translation>%1 ist vom Gerät fest auf %2 gesetzt</translation>
    </message>
    <message>
        <source>%1 has no point %2</source>
        <translation>%1 hat keinen Punkt %2</translation>
    </message>
    <message>
        <source>%1: not a number</source>
        <translation>%1: keine Zahl</translation>
    </message>
    <message>
        <source>%1 must be above %2 (%3)</source>
        <translation>%1 muss größer als %2 (%3) sein</translation>
    </message>
    <message>
        <source>%1 must be below %2 (%3)</source>
        <translation>%1 muss kleiner als %2 (%3) sein</translation>
    </message>
</context>
<context>
    <name>vt::model::LCurveTableModel</name>
    <message>
        <source>P%1</source>
        <translation>P%1</translation>
    </message>
    <message>
        <source>Point %1</source>
        <translation>Punkt %1</translation>
    </message>
    <message>
        <source>%1: input (set value) coordinate, branch %2</source>
        <translation>%1: Eingangskoordinate (Sollwert), Zweig %2</translation>
    </message>
    <message>
        <source>%1: output coordinate, branch %2</source>
        <translation>%1: Ausgangskoordinate, Zweig %2</translation>
    </message>
    <message>
        <source>%1 x (%2)</source>
        <translation>%1 x (%2)</translation>
    </message>
    <message>
        <source>%1 y (%2)</source>
        <translation>%1 y (%2)</translation>
    </message>
    <message>
        <source>no such point</source>
        <translation>kein solcher Punkt</translation>
    </message>
</context>
<context>
    <name>vt::model::ModuleGuide</name>
    <message>
        <source>Module %1 (OPAT master, PROFIBUS interface): SADR %2, fixed; no switch to set.</source>
        <translation>Modul %1 (OPAT-Master, PROFIBUS-Schnittstelle): SADR %2, fest; kein Schalter einzustellen.</translation>
    </message>
    <message>
        <source>Module %1 (OPAT master, PROFIBUS interface): SADR %2 — the master must have SADR 0.</source>
        <translation>Modul %1 (OPAT-Master, PROFIBUS-Schnittstelle): SADR %2 — der Master muss SADR 0 haben.</translation>
    </message>
    <message>
        <source>Module %1 (OPAT CAN slave): set the rotary switch to %2 (SADR %2).</source>
        <translation>Modul %1 (OPAT-CAN-Slave): Drehschalter auf %2 stellen (SADR %2).</translation>
    </message>
    <message>
        <source>Module %1 (leftmost): E22 = %2.</source>
        <translation>Modul %1 (ganz links): E22 = %2.</translation>
    </message>
    <message>
        <source>Module %1: E22 = %2.</source>
        <translation>Modul %1: E22 = %2.</translation>
    </message>
    <message>
        <source>CMD 15 does not reach it; only CMD 3 / CMD 6.</source>
        <translation>CMD 15 erreicht es nicht, nur CMD 3 / CMD 6.</translation>
    </message>
    <message>
        <source>The first module, the one with the PROFIBUS interface, is the OPAT master and always has SADR 0. The CAN slaves get SADR 1 to 7 only by their rotary switch; no parameter changes it. Two slaves on the same switch position stop the node (exception 12). (OPAT manual §1.4, §3.1)</source>
        <translation>Das erste Modul mit der PROFIBUS-Schnittstelle ist der OPAT-Master und hat immer SADR 0. Die CAN-Slaves erhalten SADR 1 bis 7 nur über ihren Drehschalter; kein Parameter ändert ihn. Zwei Slaves mit derselben Schalterstellung legen den Knoten still (Exception 12). (OPAT-Handbuch §1.4, §3.1)</translation>
    </message>
    <message>
        <source>Each DMA-2 module answers to its E22. Number them 1, 2, 3 … from the module on the left to the one next to the bus node. CMD 15 reaches addresses 1 to 5 only; modules with E22 above 5 (up to 32) are reachable with CMD 3 and CMD 6 only. (DMA manuals §1.5, §4.1)</source>
        <translation>Jedes DMA-2-Modul antwortet auf seinen E22. Von links nach rechts 1, 2, 3 … bis zum Modul neben dem Busknoten nummerieren. CMD 15 erreicht nur die Adressen 1 bis 5; Module mit E22 über 5 (bis 32) sind nur mit CMD 3 und CMD 6 erreichbar. (DMA-Handbücher §1.5, §4.1)</translation>
    </message>
    <message>
        <source>E24 = 126: the PROFIBUS master sets the address over the bus after the next power-up; the address it gives then shows in E24.</source>
        <translation>E24 = 126: Der PROFIBUS-Master vergibt die Adresse nach dem nächsten Einschalten über den Bus; sie erscheint danach in E24.</translation>
    </message>
    <message>
        <source>E24 = %1: the node&apos;s PROFIBUS address is %1; enter the same address in the PLC&apos;s hardware configuration.</source>
        <translation>E24 = %1: Die PROFIBUS-Adresse des Knotens ist %1; dieselbe Adresse in der Hardware-Konfiguration der SPS eintragen.</translation>
    </message>
    <message>
        <source>A change of E24 becomes active only after a power-down/power-up of the node.</source>
        <translation>Eine Änderung von E24 wird erst nach Aus- und Wiedereinschalten des Knotens wirksam.</translation>
    </message>
    <message>
        <source>Connect the service cable to module %1 (SADR %2), then press Next.</source>
        <translation>Das Servicekabel an Modul %1 (SADR %2) anschließen, dann Weiter drücken.</translation>
    </message>
    <message>
        <source>Connect the service cable to module %1 (E22 will become %2), then press Next.</source>
        <translation>Das Servicekabel an Modul %1 (E22 wird %2) anschließen, dann Weiter drücken.</translation>
    </message>
</context>
<context>
    <name>vt::model::MonitorScheduler</name>
    <message>
        <source>incomplete answer</source>
        <translation>unvollständige Antwort</translation>
    </message>
</context>
<context>
    <name>vt::model::MonitorSession</name>
    <message>
        <source>No channels are monitored.</source>
        <translation>Es werden keine Kanäle überwacht.</translation>
    </message>
</context>
<context>
    <name>vt::model::NumberText</name>
    <message>
        <source>“%1” is not a whole number as typed here: digits only, no thousands separators and no exponent, e.g. %2.</source>
        <translation>„%1“ ist hier keine ganze Zahl: nur Ziffern, ohne Tausendertrennzeichen und ohne Exponent, z. B. %2.</translation>
    </message>
    <message>
        <source>“%1” is not a number as typed here: digits with “%2” as the decimal sign, no thousands separators and no exponent, e.g. %3.</source>
        <translation>„%1“ ist hier keine Zahl: Ziffern mit „%2“ als Dezimalzeichen, ohne Tausendertrennzeichen und ohne Exponent, z. B. %3.</translation>
    </message>
    <message>
        <source>No number entered; type one like %1.</source>
        <translation>Keine Zahl eingegeben; geben Sie eine ein, z. B. %1.</translation>
    </message>
    <message>
        <source>“%1” is not a whole number; this field takes whole numbers only, e.g. %2.</source>
        <translation>„%1“ ist keine ganze Zahl; dieses Feld nimmt nur ganze Zahlen, z. B. %2.</translation>
    </message>
    <message>
        <source>“%1” has more than %2 digits after the decimal sign; it is not rounded. Type at most %2, e.g. %3.</source>
        <translation>Die Zahl „%1“ hat mehr als %2 Nachkommastellen; sie wird nicht gerundet. Geben Sie höchstens %2 ein, z. B. %3.</translation>
    </message>
    <message>
        <source>%1 is outside the allowed range %2 … %3.</source>
        <translation>%1 liegt außerhalb des zulässigen Bereichs %2 … %3.</translation>
    </message>
</context>
<context>
    <name>vt::model::ParamFileIo</name>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MiB: not a parameter file.</source>
        <translation>%1 ist größer als %2 MiB: keine Parameterdatei.</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
</context>
<context>
    <name>vt::model::ParameterDocument</name>
    <message>
        <source>Revert to device</source>
        <translation>Auf Gerätewerte zurücksetzen</translation>
    </message>
    <message>
        <source>Revert to file</source>
        <translation>Auf Dateiwerte zurücksetzen</translation>
    </message>
    <message>
        <source>No such parameter.</source>
        <translation>Diesen Parameter gibt es nicht.</translation>
    </message>
    <message>
        <source>%1 is read only.</source>
        <translation>%1 ist nur lesbar.</translation>
    </message>
    <message>
        <source>%1 takes a text.</source>
        <translation>%1 nimmt einen Text.</translation>
    </message>
    <message>
        <source>%1 takes a number.</source>
        <translation>%1 nimmt eine Zahl.</translation>
    </message>
    <message numerus="yes">
        <source>%1 takes at most %n character(s).</source>
        <translation>
            <numerusform>%1 nimmt höchstens %n Zeichen.</numerusform>
            <numerusform>%1 nimmt höchstens %n Zeichen.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, mode %2</source>
        <translation>%1, Modus %2</translation>
    </message>
    <message>
        <source>%1 %2, mode %3</source>
        <translation>%1 %2, Modus %3</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Module %1 of the document goes to module %2 of the node.</source>
        <translation>Modul %1 des Dokuments geht auf Modul %2 des Knotens.</translation>
    </message>
    <message>
        <source>Module %1 of the node (%2) is not in the document: not shown.</source>
        <translation>Modul %1 des Knotens (%2) ist nicht im Dokument: nicht angezeigt.</translation>
    </message>
    <message>
        <source>Module %1: the document is for %2, the device is %3. Rows the device does not apply are kept but not written.</source>
        <translation>Modul %1: das Dokument ist für %2, das Gerät ist %3. Zeilen, die für das Gerät nicht gelten, bleiben erhalten, werden aber nicht geschrieben.</translation>
    </message>
    <message>
        <source>Module %1 of the document is %2, the node&apos;s module %1 is %3: not paired, it stays offline.</source>
        <translation>Modul %1 des Dokuments ist %2, Modul %1 des Knotens ist %3: nicht zugeordnet, es bleibt offline.</translation>
    </message>
    <message>
        <source>Module %1 of the document has no module on the node: it stays offline.</source>
        <translation>Modul %1 des Dokuments hat kein Modul am Knoten: es bleibt offline.</translation>
    </message>
    <message>
        <source>module %1 %2 = %3</source>
        <translation>Modul %1 %2 = %3</translation>
    </message>
</context>
<context>
    <name>vt::model::ParameterTreeModel</name>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Zugriff</translation>
    </message>
    <message numerus="yes">
        <source>text, at most %n characters</source>
        <translation>
            <numerusform>Text, höchstens %n Zeichen</numerusform>
            <numerusform>Text, höchstens %n Zeichen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n choices</source>
        <translation>
            <numerusform>%n Auswahlmöglichkeit</numerusform>
            <numerusform>%n Auswahlmöglichkeiten</numerusform>
        </translation>
    </message>
    <message>
        <source>bit field</source>
        <translation>Bitfeld</translation>
    </message>
    <message>
        <source>Address: %1</source>
        <translation>Adresse: %1</translation>
    </message>
    <message>
        <source>Range: %1</source>
        <translation>Bereich: %1</translation>
    </message>
    <message>
        <source>Access: %1</source>
        <translation>Zugriff: %1</translation>
    </message>
    <message>
        <source>Default: %1</source>
        <translation>Vorgabe: %1</translation>
    </message>
    <message>
        <source>The display scale depends on the installation; %1 is a typical value.</source>
        <translation>Die Anzeigeskalierung hängt von der Anlage ab; %1 ist ein typischer Wert.</translation>
    </message>
    <message>
        <source>Not active for this module&apos;s version and mode.</source>
        <translation>Für Version und Modus dieses Moduls nicht aktiv.</translation>
    </message>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message>
        <source>online</source>
        <translation>online</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>offline</translation>
    </message>
    <message>
        <source>Branch %1</source>
        <translation>Zweig %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n second(s) ago</source>
        <translation>
            <numerusform>vor %n Sekunde</numerusform>
            <numerusform>vor %n Sekunden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n minute(s) ago</source>
        <translation>
            <numerusform>vor %n Minute</numerusform>
            <numerusform>vor %n Minuten</numerusform>
        </translation>
    </message>
    <message>
        <source>Read %1, before the connection was lost or renewed: not known to be on the device now. Read the device again.</source>
        <translation>Gelesen %1, bevor die Verbindung verloren oder erneuert wurde: nicht bekannt, ob der Wert jetzt auf dem Gerät ist. Gerät erneut lesen.</translation>
    </message>
    <message>
        <source>Read %1: too old to be trusted. Read the device again.</source>
        <translation>Gelesen %1: zu alt, um ihm zu trauen. Gerät erneut lesen.</translation>
    </message>
    <message>
        <source>Written %1, acknowledged by the device.</source>
        <translation>Geschrieben %1, vom Gerät bestätigt.</translation>
    </message>
    <message>
        <source>Read from the device %1.</source>
        <translation>Vom Gerät gelesen %1.</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>Live value: read from the module again and again while connected.</source>
        <translation>Live-Wert: wird bei bestehender Verbindung fortlaufend vom Modul gelesen.</translation>
    </message>
</context>
<context>
    <name>vt::model::PlcConfig</name>
    <message>
        <source>The plan has no modules.</source>
        <translation>Der Plan enthält keine Module.</translation>
    </message>
    <message>
        <source>%1 OPAT modules: one CMD 15 telegram reaches the master and at most 7 CAN slaves (8 modules; OPAT manual §1.6, §3.1).</source>
        <translation>%1 OPAT-Module: Ein CMD-15-Telegramm erreicht den Master und höchstens 7 CAN-Slaves (8 Module; OPAT-Handbuch §1.6, §3.1).</translation>
    </message>
    <message>
        <source>%1 DMA modules: CMD 15 reaches E22 = 1 … 5 only; modules above 5 are reachable by CMD 3 / CMD 6 only (DMA Profibus Anleitung §1.5, DMA Profinet manual §1.5).</source>
        <translation>%1 DMA-Module: CMD 15 erreicht nur E22 = 1 … 5; Module darüber sind nur mit CMD 3 / CMD 6 erreichbar (DMA Profibus Anleitung §1.5, DMA-Profinet-Handbuch §1.5).</translation>
    </message>
    <message>
        <source>OPAT manual §1.1 (GSD file) and §4.1 (HW Config: the CMD 15 module for the master and %1 slave(s); output at least %2 bytes, input at least 9 bytes).</source>
        <translation>OPAT-Handbuch §1.1 (GSD-Datei) und §4.1 (HW Konfig: CMD-15-Modul für den Master und %1 Slave(s); Ausgang mindestens %2 Byte, Eingang mindestens 9 Byte).</translation>
    </message>
    <message>
        <source>DMA Profinet manual §1.1 (GSDML file) and §4.5.4 (one 42-byte IN/OUT module serves every fold; the CMD 15 telegram uses the first %1 output and 9 input bytes).</source>
        <translation>DMA-Profinet-Handbuch §1.1 (GSDML-Datei) und §4.5.4 (ein IN/OUT-Modul mit 42 Byte dient jeder Modulanzahl; das CMD-15-Telegramm belegt die ersten %1 Ausgangs- und 9 Eingangsbytes).</translation>
    </message>
    <message>
        <source>DMA Profibus Anleitung §6.1.1–6.1.4: product number ending in 5 uses hcs0ea7.gsd, device DMA-22-XX and the 28-byte module; the CMD 15 telegram uses the first %1 output and 9 input bytes.</source>
        <translation>DMA Profibus Anleitung §6.1.1–6.1.4: Produktnummer mit Endziffer 5 verwendet hcs0ea7.gsd, Gerät DMA-22-XX und das 28-Byte-Modul; das CMD-15-Telegramm belegt die ersten %1 Ausgangs- und 9 Eingangsbytes.</translation>
    </message>
    <message>
        <source>DMA Profibus Anleitung §1.1 (GSD file), §5.1 (CMD 15 module, output at least %1 bytes, input at least 9 bytes).</source>
        <translation>DMA Profibus Anleitung §1.1 (GSD-Datei), §5.1 (CMD-15-Modul, Ausgang mindestens %1 Byte, Eingang mindestens 9 Byte).</translation>
    </message>
    <message>
        <source>DMA Profibus Anleitung §1.1 (GSD file), §5.1 (CMD 15 module, output at least %1 bytes, input at least 9 bytes) and §5.1.1 (no one-module CMD 15 entry in the catalogue: universal module).</source>
        <translation>DMA Profibus Anleitung §1.1 (GSD-Datei), §5.1 (CMD-15-Modul, Ausgang mindestens %1 Byte, Eingang mindestens 9 Byte) und §5.1.1 (kein CMD-15-Eintrag für ein Modul im Katalog: Universalmodul).</translation>
    </message>
    <message>
        <source>DMA Profibus Anleitung §1.1 (GSD file), §5.1 (CMD 15 module, output at least %1 bytes, input at least 9 bytes); product number not given: HCS0220.GSD assumed (§6.1.1: numbers ending in 5 use hcs0ea7.gsd).</source>
        <translation>DMA Profibus Anleitung §1.1 (GSD-Datei), §5.1 (CMD-15-Modul, Ausgang mindestens %1 Byte, Eingang mindestens 9 Byte); Produktnummer nicht angegeben: HCS0220.GSD angenommen (§6.1.1: Nummern mit Endziffer 5 verwenden hcs0ea7.gsd).</translation>
    </message>
    <message>
        <source>DMA Profibus Anleitung §1.1 (GSD file), §5.1 (CMD 15 module, output at least %1 bytes, input at least 9 bytes) and §5.1.1 (no one-module CMD 15 entry in the catalogue: universal module); product number not given: HCS0220.GSD assumed (§6.1.1: numbers ending in 5 use hcs0ea7.gsd).</source>
        <translation>DMA Profibus Anleitung §1.1 (GSD-Datei), §5.1 (CMD-15-Modul, Ausgang mindestens %1 Byte, Eingang mindestens 9 Byte) und §5.1.1 (kein CMD-15-Eintrag für ein Modul im Katalog: Universalmodul); Produktnummer nicht angegeben: HCS0220.GSD angenommen (§6.1.1: Nummern mit Endziffer 5 verwenden hcs0ea7.gsd).</translation>
    </message>
    <message>
        <source>telegram address, set by the PLC (0 … 255); change it to force an answer</source>
        <translation>Telegrammadresse, von der SPS gesetzt (0 … 255); ändern, um eine Antwort zu erzwingen</translation>
    </message>
    <message>
        <source>number of CAN slaves = %1 (the master, SADR 0, is always included)</source>
        <translation>Anzahl CAN-Slaves = %1 (der Master, SADR 0, ist immer dabei)</translation>
    </message>
    <message>
        <source>number of modules = %1</source>
        <translation>Anzahl Module = %1</translation>
    </message>
    <message>
        <source>command 15 (0x0F)</source>
        <translation>Befehl 15 (0x0F)</translation>
    </message>
    <message>
        <source>control byte (special functions, bits below)</source>
        <translation>Steuerbyte (Sonderfunktionen, Bits siehe unten)</translation>
    </message>
    <message>
        <source>%1 high byte: %2</source>
        <translation>%1 High-Byte: %2</translation>
    </message>
    <message>
        <source>%1 low byte: %2</source>
        <translation>%1 Low-Byte: %2</translation>
    </message>
    <message>
        <source>%1 high byte: %2 %3</source>
        <translation>%1 High-Byte: %2 %3</translation>
    </message>
    <message>
        <source>%1 low byte: %2 %3</source>
        <translation>%1 Low-Byte: %2 %3</translation>
    </message>
    <message>
        <source>telegram address, echoed</source>
        <translation>Telegrammadresse, zurückgesendet</translation>
    </message>
    <message>
        <source>address of the module that answered (%1, changes with every answer)</source>
        <translation>Adresse des antwortenden Moduls (%1, wechselt mit jeder Antwort)</translation>
    </message>
    <message>
        <source>command 15 (0x8F = error, byte 3 = exception)</source>
        <translation>Befehl 15 (0x8F = Fehler, Byte 3 = Exception)</translation>
    </message>
    <message>
        <source>status word high byte: HW_ENABLE, ERROR, BUS_DISABLE</source>
        <translation>Statuswort High-Byte: HW_ENABLE, ERROR, BUS_DISABLE</translation>
    </message>
    <message>
        <source>status word low byte: signals, or the error number while ERROR is set</source>
        <translation>Statuswort Low-Byte: Signale, oder die Fehlernummer solange ERROR gesetzt ist</translation>
    </message>
    <message>
        <source>%1 high byte of the module named by SADR (meaning listed per module)</source>
        <translation>%1 High-Byte des in SADR genannten Moduls (Bedeutung je Modul aufgeführt)</translation>
    </message>
    <message>
        <source>%1 low byte of the module named by SADR (meaning listed per module)</source>
        <translation>%1 Low-Byte des in SADR genannten Moduls (Bedeutung je Modul aufgeführt)</translation>
    </message>
</context>
<context>
    <name>vt::model::PlcTestBench</name>
    <message>
        <source>CMD 15 addresses 1 to %1 modules on this node, not %2.</source>
        <translation>CMD 15 adressiert auf diesem Knoten 1 bis %1 Module, nicht %2.</translation>
    </message>
    <message>
        <source>The PLC test bench needs a node image link.</source>
        <translation>Der SPS-Prüfstand braucht eine Knotenabbild-Verbindung.</translation>
    </message>
    <message>
        <source>The CMD 15 telegram for %1 modules does not fit the node&apos;s output image.</source>
        <translation>Das CMD-15-Telegramm für %1 Module passt nicht in das Ausgangsabbild des Knotens.</translation>
    </message>
</context>
<context>
    <name>vt::model::ReadAllJob</name>
    <message numerus="yes">
        <source>Module %1: %n rows not read (%2)</source>
        <translation>
            <numerusform>Modul %1: %n Zeile nicht gelesen (%2)</numerusform>
            <numerusform>Modul %1: %n Zeilen nicht gelesen (%2)</numerusform>
        </translation>
    </message>
    <message>
        <source>Module %1: %2: %3 (%4)</source>
        <translation>Modul %1: %2: %3 (%4)</translation>
    </message>
</context>
<context>
    <name>vt::model::ReferenceSession</name>
    <message>
        <source>Choose a module and a set value first.</source>
        <translation>Wählen Sie zuerst ein Modul und einen Sollwert.</translation>
    </message>
    <message>
        <source>The reference has no tests.</source>
        <translation>Die Referenz enthält keine Tests.</translation>
    </message>
    <message>
        <source>The test %1 cannot be run: %2</source>
        <translation>Der Test %1 kann nicht laufen: %2</translation>
    </message>
    <message>
        <source>Reading the settings of module %1…</source>
        <translation>Einstellungen von Modul %1 werden gelesen…</translation>
    </message>
    <message>
        <source>Stopped before a test ran.</source>
        <translation>Gestoppt, bevor ein Test lief.</translation>
    </message>
    <message>
        <source>The test %1 cannot be run.</source>
        <translation>Der Test %1 kann nicht laufen.</translation>
    </message>
    <message>
        <source>Test %1 of %2 runs…</source>
        <translation>Test %1 von %2 läuft…</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>Gestoppt.</translation>
    </message>
    <message>
        <source>Test %1 of %2 ended early: %3</source>
        <translation>Test %1 von %2 endete vorzeitig: %3</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>gestoppt</translation>
    </message>
    <message>
        <source>The set value is NOT restored after test %1: check the valve.</source>
        <translation>Der Sollwert ist nach Test %1 NICHT wiederhergestellt: prüfen Sie das Ventil.</translation>
    </message>
    <message>
        <source>All %1 tests ran; the set value is restored.</source>
        <translation>Alle %1 Tests sind gelaufen; der Sollwert ist wiederhergestellt.</translation>
    </message>
</context>
<context>
    <name>vt::model::Report</name>
    <message>
        <source>Step response</source>
        <translation>Sprungantwort</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>value (%1)</source>
        <translation>Wert (%1)</translation>
    </message>
    <message>
        <source>set value %1</source>
        <translation>Sollwert %1</translation>
    </message>
    <message>
        <source>response %1</source>
        <translation>Antwort %1</translation>
    </message>
    <message>
        <source>Bode plot: gain</source>
        <translation>Bode-Diagramm: Verstärkung</translation>
    </message>
    <message>
        <source>frequency (Hz)</source>
        <translation>Frequenz (Hz)</translation>
    </message>
    <message>
        <source>gain (dB)</source>
        <translation>Verstärkung (dB)</translation>
    </message>
    <message>
        <source>gain</source>
        <translation>Verstärkung</translation>
    </message>
    <message>
        <source>Bode plot: phase</source>
        <translation>Bode-Diagramm: Phase</translation>
    </message>
    <message>
        <source>phase (°)</source>
        <translation>Phase (°)</translation>
    </message>
    <message>
        <source>phase</source>
        <translation>Phase</translation>
    </message>
    <message>
        <source>Module %1 · %2</source>
        <translation>Modul %1 · %2</translation>
    </message>
    <message>
        <source>reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>now</source>
        <translation>jetzt</translation>
    </message>
    <message>
        <source>Customer</source>
        <translation>Kunde</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Bearbeiter</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Bemerkung</translation>
    </message>
    <message>
        <source>Date and time</source>
        <translation>Datum und Uhrzeit</translation>
    </message>
    <message>
        <source>ValveTune version</source>
        <translation>ValveTune-Version</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Parameter file (offline)</source>
        <translation>Parameterdatei (offline)</translation>
    </message>
    <message>
        <source>Reference file</source>
        <translation>Referenzdatei</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>Inbetriebnahmeprotokoll</translation>
    </message>
    <message>
        <source>unknown device</source>
        <translation>unbekanntes Gerät</translation>
    </message>
    <message>
        <source>not in the reference</source>
        <translation>nicht in der Referenz</translation>
    </message>
    <message>
        <source>Modules</source>
        <translation>Module</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>Software</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Type code / serial</source>
        <translation>Typschlüssel / Seriennummer</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Not default</source>
        <translation>Nicht Vorgabe</translation>
    </message>
    <message>
        <source>Differ from reference</source>
        <translation>Abweichend von Referenz</translation>
    </message>
    <message>
        <source>≠ default</source>
        <translation>≠ Vorgabe</translation>
    </message>
    <message>
        <source>≠ reference: %1</source>
        <translation>≠ Referenz: %1</translation>
    </message>
    <message>
        <source>No settings known for this module.</source>
        <translation>Für dieses Modul sind keine Einstellungen bekannt.</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Vorgabe</translation>
    </message>
    <message>
        <source>Marks</source>
        <translation>Markierungen</translation>
    </message>
    <message>
        <source>Write log</source>
        <translation>Schreibprotokoll</translation>
    </message>
    <message>
        <source>No writes recorded.</source>
        <translation>Keine Schreibvorgänge aufgezeichnet.</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Old → new</source>
        <translation>Alt → neu</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Workbench runs</source>
        <translation>Werkbank-Läufe</translation>
    </message>
    <message>
        <source>No workbench runs chosen for the report.</source>
        <translation>Keine Werkbank-Läufe für das Protokoll gewählt.</translation>
    </message>
    <message>
        <source>Started %1; %2 set-value writes.</source>
        <translation>Gestartet %1; %2 Sollwert-Schreibvorgänge.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>Frequency (Hz)</source>
        <translation>Frequenz (Hz)</translation>
    </message>
    <message>
        <source>Gain (dB)</source>
        <translation>Verstärkung (dB)</translation>
    </message>
    <message>
        <source>Phase (°)</source>
        <translation>Phase (°)</translation>
    </message>
    <message>
        <source>Valid</source>
        <translation>Gültig</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>nicht erreicht</translation>
    </message>
    <message>
        <source>−3 dB at %1, −90° at %2.</source>
        <translation>−3 dB bei %1, −90° bei %2.</translation>
    </message>
    <message>
        <source>Fold / PLC configuration</source>
        <translation>Knoten / SPS-Konfiguration</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>GSD file</source>
        <translation>GSD-Datei</translation>
    </message>
    <message>
        <source>GSD device</source>
        <translation>GSD-Gerät</translation>
    </message>
    <message>
        <source>GSD module</source>
        <translation>GSD-Modul</translation>
    </message>
    <message>
        <source>Output bytes (PLC → node)</source>
        <translation>Ausgangsbytes (SPS → Knoten)</translation>
    </message>
    <message>
        <source>Input bytes (node → PLC)</source>
        <translation>Eingangsbytes (Knoten → SPS)</translation>
    </message>
    <message>
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <source>SADR</source>
        <translation>SADR</translation>
    </message>
    <message>
        <source>Output bytes</source>
        <translation>Ausgangsbytes</translation>
    </message>
    <message>
        <source>Layout</source>
        <translation>Belegung</translation>
    </message>
    <message>
        <source>Drift against the reference</source>
        <translation>Drift gegenüber der Referenz</translation>
    </message>
    <message>
        <source>Reference fingerprint</source>
        <translation>Referenz-Fingerabdruck</translation>
    </message>
    <message>
        <source>Taken</source>
        <translation>Aufgenommen</translation>
    </message>
    <message>
        <source>Parameter differences</source>
        <translation>Parameterabweichungen</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>Now</source>
        <translation>Jetzt</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Step figures</source>
        <translation>Sprungkennwerte</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>± %1 %</source>
        <translation>± %1 %</translation>
    </message>
    <message>
        <source>exceeded</source>
        <translation>überschritten</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>Test</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>Kennwert</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>Änderung</translation>
    </message>
    <message>
        <source>Threshold</source>
        <translation>Schwelle</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <source>Signatures</source>
        <translation>Unterschriften</translation>
    </message>
    <message>
        <source>Commissioned by (date, name, signature)</source>
        <translation>In Betrieb genommen von (Datum, Name, Unterschrift)</translation>
    </message>
    <message>
        <source>Accepted by the customer (date, name, signature)</source>
        <translation>Abgenommen vom Kunden (Datum, Name, Unterschrift)</translation>
    </message>
    <message>
        <source>Commissioning report · %1</source>
        <translation>Inbetriebnahmeprotokoll · %1</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
    <message>
        <source>%1: the report&apos;s file name must end in .pdf, .html or .json.</source>
        <translation>%1: Der Dateiname des Protokolls muss auf .pdf, .html oder .json enden.</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>%1 kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Module %1 · %2, software %3</source>
        <translation>Modul %1 · %2, Software %3</translation>
    </message>
    <message>
        <source>Module %1 · %2, software %3, mode %4</source>
        <translation>Modul %1 · %2, Software %3, Modus %4</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Sprung</translation>
    </message>
    <message>
        <source>Set value (%1)</source>
        <translation>Sollwert (%1)</translation>
    </message>
    <message>
        <source>Dead time (s)</source>
        <translation>Totzeit (s)</translation>
    </message>
    <message>
        <source>Rise time (s)</source>
        <translation>Anstiegszeit (s)</translation>
    </message>
    <message>
        <source>Overshoot (%)</source>
        <translation>Überschwingen (%)</translation>
    </message>
    <message>
        <source>Settling ±2 % (s)</source>
        <translation>Ausregelzeit ±2 % (s)</translation>
    </message>
    <message>
        <source>Settling ±5 % (s)</source>
        <translation>Ausregelzeit ±5 % (s)</translation>
    </message>
    <message>
        <source>Steady-state error (%1)</source>
        <translation>Bleibende Regeldifferenz (%1)</translation>
    </message>
    <message>
        <source>up</source>
        <translation>auf</translation>
    </message>
    <message>
        <source>down</source>
        <translation>ab</translation>
    </message>
    <message>
        <source>Time response</source>
        <translation>Zeitverlauf</translation>
    </message>
</context>
<context>
    <name>vt::model::SampleStore</name>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>not a ValveTune sample file</source>
        <translation>keine ValveTune-Messwertdatei</translation>
    </message>
    <message>
        <source>longer than %1 bytes</source>
        <translation>länger als %1 Byte</translation>
    </message>
    <message>
        <source>a channel needs an id, a name and a unit</source>
        <translation>ein Kanal braucht eine Kennung, einen Namen und eine Einheit</translation>
    </message>
    <message>
        <source>more than %1 channels</source>
        <translation>mehr als %1 Kanäle</translation>
    </message>
    <message>
        <source>the column header does not match the channels</source>
        <translation>die Spaltenüberschrift passt nicht zu den Kanälen</translation>
    </message>
    <message>
        <source>the column header is missing</source>
        <translation>die Spaltenüberschrift fehlt</translation>
    </message>
    <message>
        <source>expected %1 columns</source>
        <translation>%1 Spalten erwartet</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a time</source>
        <translation>„%1“ ist keine Zeitangabe</translation>
    </message>
    <message>
        <source>more than %1 samples</source>
        <translation>mehr als %1 Messwerte</translation>
    </message>
    <message>
        <source>time goes backwards</source>
        <translation>die Zeit läuft rückwärts</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
</context>
<context>
    <name>vt::model::Session</name>
    <message>
        <source>The request queue is full</source>
        <translation>Die Auftragswarteschlange ist voll</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>The link %1 is not open</source>
        <translation>Die Verbindung %1 ist nicht offen</translation>
    </message>
    <message>
        <source>The request cannot be encoded for %1</source>
        <translation>Der Auftrag lässt sich für %1 nicht codieren</translation>
    </message>
    <message>
        <source>unsolicited</source>
        <translation>unaufgefordert</translation>
    </message>
    <message>
        <source>does not answer the request</source>
        <translation>beantwortet die Anfrage nicht</translation>
    </message>
    <message>
        <source>no valid frame (checksum error, corrupted or incomplete)</source>
        <translation>kein gültiges Telegramm (Prüfsummenfehler, verfälscht oder unvollständig)</translation>
    </message>
    <message numerus="yes">
        <source>No answer after %n attempt(s)</source>
        <translation>
            <numerusform>Keine Antwort nach %n Versuch</numerusform>
            <numerusform>Keine Antwort nach %n Versuchen</numerusform>
        </translation>
    </message>
    <message>
        <source>The link %1 was lost</source>
        <translation>Die Verbindung %1 ist abgerissen</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>refused by the device</source>
        <translation>vom Gerät abgelehnt</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>Verbindung verloren</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>cannot be encoded</source>
        <translation>nicht codierbar</translation>
    </message>
    <message>
        <source>warning %1: %2</source>
        <translation>Warnung %1: %2</translation>
    </message>
    <message>
        <source>exchange in progress</source>
        <translation>Austausch läuft</translation>
    </message>
</context>
<context>
    <name>vt::model::SetValueStep</name>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>%1 is %2, so the bus set value %3 alone does not drive the valve. The manual: %4 Set %1 to %5 first.</source>
        <translation>%1 ist %2, daher steuert der Bus-Sollwert %3 allein das Ventil nicht. Das Handbuch: %4 Setzen Sie zuerst %1 auf %5.</translation>
    </message>
    <message>
        <source>Reading %1 failed: %2</source>
        <translation>Lesen von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>The device is in state %1 (%2), so the bus set value %3 does not drive the valve. The manual: %4 Switch it to %5 first (%6 = 0x%7).</source>
        <translation>Das Gerät ist im Zustand %1 (%2), daher steuert der Bus-Sollwert %3 das Ventil nicht. Das Handbuch: %4 Schalten Sie es zuerst in den Zustand %5 (%6 = 0x%7).</translation>
    </message>
</context>
<context>
    <name>vt::model::SimEndpoint</name>
    <message>
        <source>expected FAMILY or FAMILY:MODULES, got &apos;%1&apos;</source>
        <translation>erwartet FAMILIE oder FAMILIE:MODULE, erhalten „%1“</translation>
    </message>
    <message>
        <source>module count &apos;%1&apos; is not 1..32</source>
        <translation>Modulanzahl „%1“ liegt nicht in 1..32</translation>
    </message>
    <message>
        <source>the built-in dictionaries do not load</source>
        <translation>die eingebauten Wörterbücher lassen sich nicht laden</translation>
    </message>
    <message>
        <source>unknown device family &apos;%1&apos;</source>
        <translation>unbekannte Gerätefamilie „%1“</translation>
    </message>
    <message>
        <source>%1 speaks HART only</source>
        <translation>%1 spricht nur HART</translation>
    </message>
    <message>
        <source>the simulator does not serve %1 over &apos;%2&apos;</source>
        <translation>der Simulator bedient %1 nicht über „%2“</translation>
    </message>
    <message>
        <source>%1 is simulated over its PROFIBUS image: dsp408-image or dsp408-gateway</source>
        <translation>%1 wird über sein PROFIBUS-Abbild simuliert: dsp408-image oder dsp408-gateway</translation>
    </message>
</context>
<context>
    <name>vt::model::TelegramLog</name>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>device exception</source>
        <translation>Geräteausnahme</translation>
    </message>
    <message>
        <source>checksum error</source>
        <translation>Prüfsummenfehler</translation>
    </message>
    <message>
        <source>malformed</source>
        <translation>fehlerhaft</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>Zeitüberschreitung</translation>
    </message>
    <message>
        <source>unmatched</source>
        <translation>nicht zugeordnet</translation>
    </message>
    <message>
        <source>out</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>in</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>no reply: %1</source>
        <translation>keine Antwort: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n Byte</numerusform>
            <numerusform>%n Byte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>ValveTune telegram log: %n record(s)</source>
        <translation>
            <numerusform>ValveTune-Telegrammprotokoll: %n Eintrag</numerusform>
            <numerusform>ValveTune-Telegrammprotokoll: %n Einträge</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n older record(s) dropped</source>
        <translation>
            <numerusform>%n älterer Eintrag verworfen</numerusform>
            <numerusform>%n ältere Einträge verworfen</numerusform>
        </translation>
    </message>
    <message>
        <source>module %1</source>
        <translation>Modul %1</translation>
    </message>
</context>
<context>
    <name>vt::model::TelegramLogModel</name>
    <message>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>Richt.</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
</context>
<context>
    <name>vt::model::TelegramRecorder</name>
    <message>
        <source>no answer to attempt %1</source>
        <translation>keine Antwort auf Versuch %1</translation>
    </message>
</context>
<context>
    <name>vt::model::TestRun</name>
    <message>
        <source>Switching the set-value source %1 failed: %2</source>
        <translation>Das Umschalten der Sollwertquelle %1 ist fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Switching the set-value source failed.</source>
        <translation>Das Umschalten der Sollwertquelle ist fehlgeschlagen.</translation>
    </message>
    <message>
        <source>The module has no set value a test can drive.</source>
        <translation>Das Modul hat keinen Sollwert, den ein Test vorgeben kann.</translation>
    </message>
    <message>
        <source>%1 cannot be written.</source>
        <translation>%1 kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>The signal reaches %1, outside %2: %3</source>
        <translation>Das Signal erreicht %1, außerhalb von %2: %3</translation>
    </message>
    <message>
        <source>The window must be more than 0.</source>
        <translation>Das Fenster muss größer als 0 sein.</translation>
    </message>
    <message>
        <source>A window needs an actual value to watch.</source>
        <translation>Ein Fenster braucht einen Istwert, den es überwacht.</translation>
    </message>
    <message>
        <source>The window is in %1, the unit of %2; %3 is in %4.</source>
        <translation>Das Fenster ist in %1, der Einheit von %2; %3 ist in %4.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>Reading the set value and its source failed: %1</source>
        <translation>Das Lesen des Sollwerts und seiner Quelle ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Writing %1 failed: %2</source>
        <translation>Das Schreiben von %1 ist fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Reading the recorded values failed: %1</source>
        <translation>Das Lesen der aufgezeichneten Werte ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>The module reports an error: %1 = %2.</source>
        <translation>Das Modul meldet einen Fehler: %1 = %2.</translation>
    </message>
    <message>
        <source>%1 holds %2, not the %3 written: something else writes the set value.</source>
        <translation>%1 hat %2, nicht die geschriebenen %3: etwas anderes schreibt den Sollwert.</translation>
    </message>
    <message>
        <source>%1 = %2 left the travel window %3 … %4.</source>
        <translation>%1 = %2 hat das Verfahrfenster %3 … %4 verlassen.</translation>
    </message>
    <message>
        <source>%1 cannot be put back: its value before the test could not be read.</source>
        <translation>%1 kann nicht zurückgesetzt werden: sein Wert vor dem Test konnte nicht gelesen werden.</translation>
    </message>
</context>
<context>
    <name>vt::model::TuningJournal</name>
    <message>
        <source>module %1: %2</source>
        <translation>Modul %1: %2</translation>
    </message>
</context>
<context>
    <name>vt::model::WriteJob</name>
    <message>
        <source>unknown parameter</source>
        <translation>unbekannter Parameter</translation>
    </message>
    <message>
        <source>%1 is not writable</source>
        <translation>%1 ist nicht beschreibbar</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>acknowledged; not read back</source>
        <translation>bestätigt; nicht zurückgelesen</translation>
    </message>
    <message>
        <source>sent, but no answer (%1): the value may or may not be on the device</source>
        <translation>gesendet, aber keine Antwort (%1): der Wert ist möglicherweise im Gerät, möglicherweise nicht</translation>
    </message>
    <message>
        <source>read back %1, expected %2</source>
        <translation>zurückgelesen %1, erwartet %2</translation>
    </message>
    <message>
        <source>acknowledged; the read back failed (%1)</source>
        <translation>bestätigt; das Zurücklesen schlug fehl (%1)</translation>
    </message>
    <message>
        <source>found on the device after the interruption</source>
        <translation>nach der Unterbrechung im Gerät vorgefunden</translation>
    </message>
    <message>
        <source>not sent: the write stopped (%1)</source>
        <translation>nicht gesendet: das Schreiben wurde beendet (%1)</translation>
    </message>
    <message>
        <source>pending</source>
        <translation>ausstehend</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>unverändert</translation>
    </message>
    <message>
        <source>refused before sending</source>
        <translation>vor dem Senden abgelehnt</translation>
    </message>
    <message>
        <source>verified</source>
        <translation>geprüft</translation>
    </message>
    <message>
        <source>written, not verified</source>
        <translation>geschrieben, nicht geprüft</translation>
    </message>
    <message>
        <source>refused by the device</source>
        <translation>vom Gerät abgelehnt</translation>
    </message>
    <message>
        <source>read back differs</source>
        <translation>Rücklesewert weicht ab</translation>
    </message>
    <message>
        <source>uncertain</source>
        <translation>ungewiss</translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>nicht gesendet</translation>
    </message>
    <message>
        <source>%1 expects text</source>
        <translation>%1 erwartet einen Text</translation>
    </message>
    <message>
        <source>%1 expects a number</source>
        <translation>%1 erwartet eine Zahl</translation>
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
<context>
    <name>vt::ui::ActuatorConfirm</name>
    <message>
        <source>Module %1: %2 (%3) %4 → %5</source>
        <translation>Modul %1: %2 (%3) %4 → %5</translation>
    </message>
    <message>
        <source>This Write Can Move the Valve</source>
        <translation>Dieses Schreiben kann das Ventil bewegen</translation>
    </message>
    <message>
        <source>These values drive the actuator. The axis may move as soon as they are written.

%1

Write them?</source>
        <translation>Diese Werte steuern den Antrieb. Die Achse kann sich bewegen, sobald sie geschrieben sind.

%1

Schreiben?</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <source>Put Back What Was Changed?</source>
        <translation>Geänderte Werte zurücksetzen?</translation>
    </message>
    <message>
        <source>%1 ValveTune changed values that drive the actuator:

%2

Put the original values back?</source>
        <translation>%1 ValveTune hat Werte geändert, die den Antrieb steuern:

%2

Die ursprünglichen Werte zurückschreiben?</translation>
    </message>
    <message>
        <source>Put Back</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Leave As Is</source>
        <translation>So lassen</translation>
    </message>
</context>
<context>
    <name>vt::ui::BodePlot</name>
    <message>
        <source>run %1</source>
        <translation>Lauf %1</translation>
    </message>
    <message>
        <source>gain (dB)</source>
        <translation>Verstärkung (dB)</translation>
    </message>
    <message>
        <source>phase (°)</source>
        <translation>Phase (°)</translation>
    </message>
    <message>
        <source>frequency (Hz)</source>
        <translation>Frequenz (Hz)</translation>
    </message>
</context>
<context>
    <name>vt::ui::CanPage</name>
    <message>
        <source>CAN (CANopen)</source>
        <translation>CAN (CANopen)</translation>
    </message>
    <message>
        <source>Type the CAN interface (can0, vcan0 …).</source>
        <translation>Geben Sie die CAN-Schnittstelle ein (can0, vcan0 …).</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a network interface name.</source>
        <translation>&quot;%1&quot; ist kein Name einer Netzwerkschnittstelle.</translation>
    </message>
    <message>
        <source>CANopen node id %1 is outside %2..%3.</source>
        <translation>CANopen-Knoten-ID %1 liegt außerhalb von %2..%3.</translation>
    </message>
    <message>
        <source>&amp;Interface:</source>
        <translation>&amp;Schnittstelle:</translation>
    </message>
    <message>
        <source>&amp;Node id:</source>
        <translation>&amp;Knoten-ID:</translation>
    </message>
    <message>
        <source>&amp;Device:</source>
        <translation>&amp;Gerät:</translation>
    </message>
    <message>
        <source>HCS module (objects 0x2000 + ID)</source>
        <translation>HCS-Modul (Objekte 0x2000 + ID)</translation>
    </message>
    <message>
        <source>Wandfluh ED1 (CiA 408)</source>
        <translation>Wandfluh ED1 (CiA 408)</translation>
    </message>
    <message>
        <source>Pro&amp;duct:</source>
        <translation>Pro&amp;dukt:</translation>
    </message>
</context>
<context>
    <name>vt::ui::ChannelChooser</name>
    <message>
        <source>Monitor channels</source>
        <translation>Monitor-Kanäle</translation>
    </message>
    <message>
        <source>Tick the live values to plot. Each module is polled in one request per sample, so more modules share the link&apos;s rate; changing a module&apos;s channels starts its recording anew.</source>
        <translation>Kreuzen Sie die Live-Werte an, die angezeigt werden sollen. Jedes Modul wird mit einer Anfrage je Messwert abgefragt, mehrere Module teilen sich also die Rate der Verbindung; wenn Sie die Kanäle eines Moduls ändern, beginnt seine Aufzeichnung neu.</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
</context>
<context>
    <name>vt::ui::CompareDialog</name>
    <message>
        <source>Compare</source>
        <translation>Vergleich</translation>
    </message>
    <message>
        <source>No differences.</source>
        <translation>Keine Unterschiede.</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) differ. Tick &quot;Take other&quot; for each value to take into this document.</source>
        <translation>
            <numerusform>%n Parameter weicht ab. Kreuzen Sie &quot;Übernehmen&quot; bei jedem Wert an, der in dieses Dokument übernommen werden soll.</numerusform>
            <numerusform>%n Parameter weichen ab. Kreuzen Sie &quot;Übernehmen&quot; bei jedem Wert an, der in dieses Dokument übernommen werden soll.</numerusform>
        </translation>
    </message>
    <message>
        <source>Tick All</source>
        <translation>Alle ankreuzen</translation>
    </message>
    <message>
        <source>Tick None</source>
        <translation>Keine ankreuzen</translation>
    </message>
    <message numerus="yes">
        <source>Apply %n Ticked Value(s)</source>
        <translation>
            <numerusform>%n angekreuzten Wert übernehmen</numerusform>
            <numerusform>%n angekreuzte Werte übernehmen</numerusform>
        </translation>
    </message>
    <message>
        <source>Tick the values to take; nothing changes until you apply them.</source>
        <translation>Kreuzen Sie die zu übernehmenden Werte an; nichts ändert sich, bevor Sie sie übernehmen.</translation>
    </message>
    <message numerus="yes">
        <source>Apply puts %n ticked value(s) into this document as one step (Edit ▸ Undo takes it back). Nothing is written to the device until Device ▸ Write Changes.</source>
        <translation>
            <numerusform>Übernehmen setzt %n angekreuzten Wert in einem Schritt in dieses Dokument (Bearbeiten ▸ Rückgängig nimmt ihn zurück). Zum Gerät wird erst mit Gerät ▸ Änderungen schreiben geschrieben.</numerusform>
            <numerusform>Übernehmen setzt %n angekreuzte Werte in einem Schritt in dieses Dokument (Bearbeiten ▸ Rückgängig nimmt sie zurück). Zum Gerät wird erst mit Gerät ▸ Änderungen schreiben geschrieben.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vt::ui::ComposePanel</name>
    <message>
        <source>%1: not a number</source>
        <translation>%1: keine Zahl</translation>
    </message>
    <message>
        <source>Long address: device type 0..0xFFFF, device id 0..0xFFFFFF</source>
        <translation>Lange Adresse: Gerätetyp 0..0xFFFF, Geräte-ID 0..0xFFFFFF</translation>
    </message>
    <message>
        <source>Data: not hex</source>
        <translation>Daten: nicht hexadezimal</translation>
    </message>
    <message>
        <source>Modules: &quot;CTRL,VALUE1,VALUE2&quot; per module (0..255, two -32768..32767), separated by &quot;;&quot;</source>
        <translation>Module: &quot;CTRL,VALUE1,VALUE2&quot; je Modul (0..255, zweimal -32768..32767), getrennt durch &quot;;&quot;</translation>
    </message>
    <message>
        <source>Nothing to send: the fields do not make a frame.</source>
        <translation>Nichts zu senden: Die Felder ergeben kein Telegramm.</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>Nicht verbunden.</translation>
    </message>
    <message>
        <source>Waiting for the answer to the last frame.</source>
        <translation>Warte auf die Antwort auf das letzte Telegramm.</translation>
    </message>
    <message>
        <source>No link of ValveTune carries %1 frames (PROFIBUS DP needs a master card); copy the bytes instead.</source>
        <translation>Keine Verbindung von ValveTune überträgt %1-Telegramme (PROFIBUS DP braucht eine Masterkarte); kopieren Sie stattdessen die Bytes.</translation>
    </message>
    <message>
        <source>The current link speaks %1; this frame needs %2.</source>
        <translation>Die aktuelle Verbindung spricht %1; dieses Telegramm braucht %2.</translation>
    </message>
    <message>
        <source>This frame changes the device:
%1

Send it?</source>
        <translation>Dieses Telegramm verändert das Gerät:
%1

Senden?</translation>
    </message>
    <message>
        <source>Send a write</source>
        <translation>Schreibzugriff senden</translation>
    </message>
    <message>
        <source>Sent; waiting for the answer…</source>
        <translation>Gesendet; warte auf Antwort…</translation>
    </message>
    <message>
        <source>Answered: %1</source>
        <translation>Antwort: %1</translation>
    </message>
    <message>
        <source>HCS CMD 3 read</source>
        <translation>HCS CMD 3 lesen</translation>
    </message>
    <message>
        <source>HCS CMD 6 write</source>
        <translation>HCS CMD 6 schreiben</translation>
    </message>
    <message>
        <source>HCS CMD 15 cyclic</source>
        <translation>HCS CMD 15 zyklisch</translation>
    </message>
    <message>
        <source>Modbus FC 3 read</source>
        <translation>Modbus FC 3 lesen</translation>
    </message>
    <message>
        <source>Modbus FC 6 write</source>
        <translation>Modbus FC 6 schreiben</translation>
    </message>
    <message>
        <source>PKW read</source>
        <translation>PKW lesen</translation>
    </message>
    <message>
        <source>PKW write</source>
        <translation>PKW schreiben</translation>
    </message>
    <message>
        <source>HART command</source>
        <translation>HART-Kommando</translation>
    </message>
    <message>
        <source>HART parameter read (128/130/132)</source>
        <translation>HART-Parameter lesen (128/130/132)</translation>
    </message>
    <message>
        <source>HART parameter write (129/131/133)</source>
        <translation>HART-Parameter schreiben (129/131/133)</translation>
    </message>
    <message>
        <source>SDO upload (read)</source>
        <translation>SDO-Upload (lesen)</translation>
    </message>
    <message>
        <source>SDO download (write)</source>
        <translation>SDO-Download (schreiben)</translation>
    </message>
    <message>
        <source>1 byte</source>
        <translation>1 Byte</translation>
    </message>
    <message>
        <source>2 bytes</source>
        <translation>2 Bytes</translation>
    </message>
    <message>
        <source>4 bytes</source>
        <translation>4 Bytes</translation>
    </message>
    <message>
        <source>Modbus TCP (MBAP header)</source>
        <translation>Modbus TCP (MBAP-Header)</translation>
    </message>
    <message>
        <source>Frame:</source>
        <translation>Telegramm:</translation>
    </message>
    <message>
        <source>Family:</source>
        <translation>Familie:</translation>
    </message>
    <message>
        <source>Framing:</source>
        <translation>Rahmenformat:</translation>
    </message>
    <message>
        <source>TADR:</source>
        <translation>TADR:</translation>
    </message>
    <message>
        <source>SADR (module):</source>
        <translation>SADR (Modul):</translation>
    </message>
    <message>
        <source>Unit id:</source>
        <translation>Unit-ID:</translation>
    </message>
    <message>
        <source>Transaction id:</source>
        <translation>Transaktions-ID:</translation>
    </message>
    <message>
        <source>Parameter ID / register:</source>
        <translation>Parameter-ID / Register:</translation>
    </message>
    <message>
        <source>Count:</source>
        <translation>Anzahl:</translation>
    </message>
    <message>
        <source>Value (raw):</source>
        <translation>Rohwert:</translation>
    </message>
    <message>
        <source>Modules (CTRL,V1,V2; …):</source>
        <translation>Module (CTRL,V1,V2; …):</translation>
    </message>
    <message>
        <source>IND:</source>
        <translation>IND:</translation>
    </message>
    <message>
        <source>PNU:</source>
        <translation>PNU:</translation>
    </message>
    <message>
        <source>Instance:</source>
        <translation>Instanz:</translation>
    </message>
    <message>
        <source>Poll address:</source>
        <translation>Polling-Adresse:</translation>
    </message>
    <message>
        <source>Device type (long frame):</source>
        <translation>Gerätetyp (langes Telegramm):</translation>
    </message>
    <message>
        <source>Device id (long frame):</source>
        <translation>Geräte-ID (langes Telegramm):</translation>
    </message>
    <message>
        <source>Command:</source>
        <translation>Kommando:</translation>
    </message>
    <message>
        <source>Data (hex):</source>
        <translation>Daten (hex):</translation>
    </message>
    <message>
        <source>Node id:</source>
        <translation>Knoten-ID:</translation>
    </message>
    <message>
        <source>Object index:</source>
        <translation>Objektindex:</translation>
    </message>
    <message>
        <source>Sub-index:</source>
        <translation>Subindex:</translation>
    </message>
    <message>
        <source>Width:</source>
        <translation>Breite:</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>This frame changes the device:
%1
%2

Send it?</source>
        <translation>Dieser Rahmen ändert das Gerät:
%1
%2

Senden?</translation>
    </message>
    <message>
        <source>No parameter of the module&apos;s dictionary has this address: the editor&apos;s Device column cannot follow it. Read the device again.</source>
        <translation>Kein Parameter im Wörterbuch des Moduls hat diese Adresse: die Gerätespalte des Editors kann nicht folgen. Gerät erneut lesen.</translation>
    </message>
    <message>
        <source>%1 must be %2 to %3.</source>
        <translation>%1 muss %2 bis %3 sein.</translation>
    </message>
    <message>
        <source>Answered: %1 (%2)</source>
        <translation>Antwort: %1 (%2)</translation>
    </message>
</context>
<context>
    <name>vt::ui::ConnectDialog</name>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>C&amp;onnect</source>
        <translation>&amp;Verbinden</translation>
    </message>
</context>
<context>
    <name>vt::ui::DecodePanel</name>
    <message>
        <source>Paste or type a frame as hex (&quot;23 00 06&quot;, &quot;0x23,0x00&quot;, &quot;230006&quot;) or a CAN frame as &quot;605#40416000&quot;.</source>
        <translation>Fügen Sie ein Telegramm als Hex ein oder geben Sie es ein (&quot;23 00 06&quot;, &quot;0x23,0x00&quot;, &quot;230006&quot;), ein CAN-Telegramm als &quot;605#40416000&quot;.</translation>
    </message>
    <message>
        <source>Too long: at most %1 characters.</source>
        <translation>Zu lang: höchstens %1 Zeichen.</translation>
    </message>
    <message>
        <source>Not hex at character %1.</source>
        <translation>Kein Hex-Zeichen an Stelle %1.</translation>
    </message>
    <message>
        <source>Auto cannot decide: the bytes are no frame of any protocol ValveTune knows. Choose a protocol to see why.</source>
        <translation>Auto kann nicht entscheiden: Die Bytes sind kein Telegramm eines Protokolls, das ValveTune kennt. Wählen Sie ein Protokoll, um den Grund zu sehen.</translation>
    </message>
    <message>
        <source>Auto cannot decide between %1. Choose the protocol.</source>
        <translation>Auto kann nicht zwischen %1 entscheiden. Wählen Sie das Protokoll.</translation>
    </message>
    <message>
        <source>Auto: %1 (%2).</source>
        <translation>Auto: %1 (%2).</translation>
    </message>
    <message>
        <source>request</source>
        <translation>Anfrage</translation>
    </message>
    <message>
        <source>response</source>
        <translation>Antwort</translation>
    </message>
    <message>
        <source>The frame is not valid.</source>
        <translation>Das Telegramm ist ungültig.</translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s).</source>
        <translation>
            <numerusform>%n Byte.</numerusform>
            <numerusform>%n Byte.</numerusform>
        </translation>
    </message>
    <message>
        <source>Hex bytes, e.g. 23 00 06 00 30 03 E8</source>
        <translation>Hex-Bytes, z. B. 23 00 06 00 30 03 E8</translation>
    </message>
    <message>
        <source>Protocol:</source>
        <translation>Protokoll:</translation>
    </message>
    <message>
        <source>Family:</source>
        <translation>Familie:</translation>
    </message>
    <message>
        <source>Direction:</source>
        <translation>Richtung:</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>request (master → device)</source>
        <translation>Anfrage (Master → Gerät)</translation>
    </message>
    <message>
        <source>response (device → master)</source>
        <translation>Antwort (Gerät → Master)</translation>
    </message>
    <message>
        <source>Auto: %1 (%2) with a wrong CRC.</source>
        <translation>Automatisch: %1 (%2) mit falscher CRC.</translation>
    </message>
</context>
<context>
    <name>vt::ui::DictionaryTexts</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
</context>
<context>
    <name>vt::ui::Dsp408Fields</name>
    <message>
        <source>O&amp;utput image at register:</source>
        <translation>A&amp;usgangsabbild ab Register:</translation>
    </message>
    <message>
        <source>First register of the ED1&apos;s output image (PKW request and PZD, 7 registers) in the gateway&apos;s map; written with FC 16.</source>
        <translation>Erstes Register des Ausgangsabbilds der ED1 (PKW-Auftrag und PZD, 7 Register) in der Zuordnung des Gateways; geschrieben mit FC 16.</translation>
    </message>
    <message>
        <source>I&amp;nput image at register:</source>
        <translation>E&amp;ingangsabbild ab Register:</translation>
    </message>
    <message>
        <source>First register of the ED1&apos;s input image (PKW response and PZD, 7 registers) in the gateway&apos;s map.</source>
        <translation>Erstes Register des Eingangsabbilds der ED1 (PKW-Antwort und PZD, 7 Register) in der Zuordnung des Gateways.</translation>
    </message>
    <message>
        <source>Input image read &amp;with:</source>
        <translation>Eingangsabbild lesen &amp;mit:</translation>
    </message>
    <message>
        <source>FC 3 (holding registers)</source>
        <translation>FC 3 (Holding-Register)</translation>
    </message>
    <message>
        <source>FC 4 (input registers)</source>
        <translation>FC 4 (Input-Register)</translation>
    </message>
    <message>
        <source>Image &amp;bytes in a register:</source>
        <translation>Abbild-&amp;Bytes in einem Register:</translation>
    </message>
    <message>
        <source>First byte high (as Modbus)</source>
        <translation>Erstes Byte oben (wie Modbus)</translation>
    </message>
    <message>
        <source>First byte low (swapped)</source>
        <translation>Erstes Byte unten (vertauscht)</translation>
    </message>
    <message>
        <source>32-bit PZD &amp;values:</source>
        <translation>32-Bit-PZD-&amp;Werte:</translation>
    </message>
    <message>
        <source>High word first (the manual&apos;s examples)</source>
        <translation>High-Wort zuerst (Beispiele des Handbuchs)</translation>
    </message>
    <message>
        <source>Low word first</source>
        <translation>Low-Wort zuerst</translation>
    </message>
    <message>
        <source>PKW &amp;IND in:</source>
        <translation>PKW-&amp;IND in:</translation>
    </message>
    <message>
        <source>Byte 2 (the manual&apos;s example)</source>
        <translation>Byte 2 (Beispiel des Handbuchs)</translation>
    </message>
    <message>
        <source>Byte 3</source>
        <translation>Byte 3</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldAddressPage</name>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message>
        <source>E24 stays as it is on the master.</source>
        <translation>E24 bleibt am Master unverändert.</translation>
    </message>
    <message>
        <source>Addresses</source>
        <translation>Adressen</translation>
    </message>
    <message>
        <source>Which address each module answers to, and how to set it.</source>
        <translation>Auf welche Adresse jedes Modul antwortet und wie sie eingestellt wird.</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>What to do</source>
        <translation>Vorgehen</translation>
    </message>
    <message>
        <source>Number 1, 2, 3 … from the left</source>
        <translation>Nummer 1, 2, 3 … von links</translation>
    </message>
    <message>
        <source>Set the master&apos;s PROFIBUS address E24 to</source>
        <translation>PROFIBUS-Adresse E24 des Masters setzen auf</translation>
    </message>
    <message>
        <source>126 = the PROFIBUS master sets the address over the bus</source>
        <translation>126 = der PROFIBUS-Master setzt die Adresse über den Bus</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldApplyPage</name>
    <message>
        <source>not applied</source>
        <translation>nicht angewendet</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>running …</source>
        <translation>läuft …</translation>
    </message>
    <message>
        <source>done, found by the scan</source>
        <translation>fertig, von der Abfrage gefunden</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message>
        <source>Offline planning: no node is connected, so nothing is written. Next continues to the PLC configuration.</source>
        <translation>Offline-Planung: Es ist kein Knoten verbunden, daher wird nichts geschrieben. „Weiter“ führt zur SPS-Konfiguration.</translation>
    </message>
    <message>
        <source>Writes each module&apos;s address and options (range-checked, read back), then identifies every planned address. Connection: %1</source>
        <translation>Schreibt Adresse und Optionen jedes Moduls (bereichsgeprüft, zurückgelesen) und identifiziert dann jede geplante Adresse. Verbindung: %1</translation>
    </message>
    <message>
        <source>Apply to module %1</source>
        <translation>Auf Modul %1 anwenden</translation>
    </message>
    <message>
        <source>Apply to the node</source>
        <translation>Auf den Knoten anwenden</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Write the addresses and options to the modules and check that every module answers.</source>
        <translation>Adressen und Optionen in die Module schreiben und prüfen, dass jedes Modul antwortet.</translation>
    </message>
    <message>
        <source>Point-to-point cable: one module at a time</source>
        <translation>Punkt-zu-Punkt-Kabel: ein Modul nach dem anderen</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Writes and notes</source>
        <translation>Schreibvorgänge und Hinweise</translation>
    </message>
    <message>
        <source>Module at address %1: the plan&apos;s options, then address %2</source>
        <translation>Modul an Adresse %1: die Optionen des Plans, dann Adresse %2</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldBenchPage</name>
    <message>
        <source>Module %1 (SADR %2)</source>
        <translation>Modul %1 (SADR %2)</translation>
    </message>
    <message>
        <source>error %1</source>
        <translation>Fehler %1</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%n answer(s))</source>
        <translation>
            <numerusform>%1 (%n Antwort)</numerusform>
            <numerusform>%1 (%n Antworten)</numerusform>
        </translation>
    </message>
    <message>
        <source>Telegrams sent %1, answers %2, stale %3, exceptions %4, no answer %5; TADR %6</source>
        <translation>Gesendete Telegramme %1, Antworten %2, veraltet %3, Ausnahmen %4, keine Antwort %5; TADR %6</translation>
    </message>
    <message>
        <source>Sends CMD 15 to every module with the values below, TADR changing every telegram, and shows each module&apos;s answer as the node multiplexes them (DMA Profinet manual §4.2, OPAT manual §3.2).</source>
        <translation>Sendet CMD 15 mit den Werten unten an jedes Modul, mit wechselnder TADR in jedem Telegramm, und zeigt die Antwort jedes Moduls, wie der Knoten sie multiplext (DMA-Profinet-Handbuch §4.2, OPAT-Handbuch §3.2).</translation>
    </message>
    <message>
        <source>PLC test bench</source>
        <translation>SPS-Prüfstand</translation>
    </message>
    <message>
        <source>The check a PLC programmer does: cyclic CMD 15 telegrams and the decoded answers.</source>
        <translation>Die Prüfung eines SPS-Programmierers: zyklische CMD-15-Telegramme und die dekodierten Antworten.</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Control byte</source>
        <translation>Steuer-Byte</translation>
    </message>
    <message>
        <source>VALUE1 out</source>
        <translation>VALUE1 aus</translation>
    </message>
    <message>
        <source>VALUE2 out</source>
        <translation>VALUE2 aus</translation>
    </message>
    <message>
        <source>Status word</source>
        <translation>Statuswort</translation>
    </message>
    <message>
        <source>VALUE1 in</source>
        <translation>VALUE1 ein</translation>
    </message>
    <message>
        <source>VALUE2 in</source>
        <translation>VALUE2 ein</translation>
    </message>
    <message>
        <source>Recent TADR</source>
        <translation>Letzte TADR</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Cycle:</source>
        <translation>Zyklus:</translation>
    </message>
    <message>
        <source>Connect the node&apos;s fieldbus gateway over TCP with the protocol &quot;node-image&quot; (Device ▸ Connect…), or the simulator with the protocol &quot;node-image&quot;.</source>
        <translation>Verbinden Sie das Feldbus-Gateway des Knotens über TCP mit dem Protokoll &quot;node-image&quot; (Gerät ▸ Verbinden…) oder den Simulator mit dem Protokoll &quot;node-image&quot;.</translation>
    </message>
    <message>
        <source>Not available: no node is connected.</source>
        <translation>Nicht verfügbar: Kein Knoten ist verbunden.</translation>
    </message>
    <message>
        <source>Not available: the connection speaks %1, and the test bench needs the node&apos;s cyclic CMD 15 image.</source>
        <translation>Nicht verfügbar: Die Verbindung spricht %1, der Prüfstand braucht aber das zyklische CMD-15-Abbild des Knotens.</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldCheckPage</name>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s) must be fixed before the plan can be applied; go Back to change it.</source>
        <translation>
            <numerusform>%n Fehler muss behoben werden, bevor der Plan angewendet werden kann; gehen Sie zurück, um ihn zu ändern.</numerusform>
            <numerusform>%n Fehler müssen behoben werden, bevor der Plan angewendet werden kann; gehen Sie zurück, um ihn zu ändern.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>No errors; %n warning(s) to read.</source>
        <translation>
            <numerusform>Keine Fehler; %n Warnung zu lesen.</numerusform>
            <numerusform>Keine Fehler; %n Warnungen zu lesen.</numerusform>
        </translation>
    </message>
    <message>
        <source>The plan passes every check.</source>
        <translation>Der Plan besteht alle Prüfungen.</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source>What the manuals say about this plan. Errors block Next.</source>
        <translation>Was die Handbücher zu diesem Plan sagen. Fehler sperren „Weiter“.</translation>
    </message>
    <message>
        <source>The PLC program already exists; the SNUM it sends:</source>
        <translation>Das SPS-Programm existiert bereits; die SNUM, die es sendet:</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Schweregrad</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>Befund</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldModulesPage</name>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message>
        <source> (master)</source>
        <translation> (Master)</translation>
    </message>
    <message>
        <source> (CAN slave)</source>
        <translation> (CAN-Slave)</translation>
    </message>
    <message>
        <source>V%1</source>
        <translation>V%1</translation>
    </message>
    <message>
        <source>Mode %1</source>
        <translation>Modus %1</translation>
    </message>
    <message>
        <source>Scan finished: no module answered.</source>
        <translation>Abfrage beendet: Kein Modul hat geantwortet.</translation>
    </message>
    <message numerus="yes">
        <source>Scan finished: %n module(s) at address %1.</source>
        <translation>
            <numerusform>Abfrage beendet: %n Modul an Adresse %1.</numerusform>
            <numerusform>Abfrage beendet: %n Module an den Adressen %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Scanning address %1 …</source>
        <translation>Adresse %1 wird abgefragt …</translation>
    </message>
    <message>
        <source>Modules</source>
        <translation>Module</translation>
    </message>
    <message>
        <source>How many modules the node has and which software and mode each runs. Scan the connected node, or enter them for offline planning.</source>
        <translation>Wie viele Module der Knoten hat und welche Software und welchen Modus jedes betreibt. Fragen Sie den verbundenen Knoten ab oder geben Sie die Module für eine Offline-Planung ein.</translation>
    </message>
    <message>
        <source>Modules on the node:</source>
        <translation>Module am Knoten:</translation>
    </message>
    <message>
        <source>Scan the connected node</source>
        <translation>Verbundenen Knoten abfragen</translation>
    </message>
    <message>
        <source>Identifies every address of the connection and takes the modules that answer.</source>
        <translation>Identifiziert jede Adresse der Verbindung und übernimmt die Module, die antworten.</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>Software</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Name (for the PLC sheet)</source>
        <translation>Name (für das SPS-Blatt)</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldNodePage</name>
    <message>
        <source>The OPAT master carries the PROFIBUS interface (SADR 0) and drives up to seven OPAT CAN slaves (SADR 1 to 7 by rotary switch). One CMD 15 telegram reaches all eight. (OPAT manual §1.4, §3)</source>
        <translation>Der OPAT-Master trägt die PROFIBUS-Schnittstelle (SADR 0) und steuert bis zu sieben OPAT-CAN-Slaves (SADR 1 bis 7 per Drehschalter). Ein CMD-15-Telegramm erreicht alle acht. (OPAT-Handbuch §1.4, §3)</translation>
    </message>
    <message>
        <source>DMA-2 modules behind a PROFIBUS node module; each module answers to its E22. CMD 15 reaches E22 = 1 to 5. The node&apos;s product number decides the GSD file. (DMA Profibus Anleitung §1.3, §4–5)</source>
        <translation>DMA-2-Module hinter einem PROFIBUS-Knotenmodul; jedes Modul antwortet auf seine E22. CMD 15 erreicht E22 = 1 bis 5. Die Produktnummer des Knotens bestimmt die GSD-Datei. (DMA Profibus Anleitung §1.3, §4–5)</translation>
    </message>
    <message>
        <source>DMA-2 modules behind a PROFINET node module; each module answers to its E22. CMD 15 reaches E22 = 1 to 5. (DMA Profinet manual §1.3, §4–5)</source>
        <translation>DMA-2-Module hinter einem PROFINET-Knotenmodul; jedes Modul antwortet auf seine E22. CMD 15 erreicht E22 = 1 bis 5. (DMA-Profinet-Handbuch §1.3, §4–5)</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Knotentyp</translation>
    </message>
    <message>
        <source>Which kind of node are you setting up?</source>
        <translation>Welche Art von Knoten richten Sie ein?</translation>
    </message>
    <message>
        <source>Product number of the node:</source>
        <translation>Produktnummer des Knotens:</translation>
    </message>
    <message>
        <source>e.g. 5 005 123 45</source>
        <translation>z. B. 5 005 123 45</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldOptionsPage</name>
    <message>
        <source>Module %1 — %2, V%3, mode %4</source>
        <translation>Modul %1 — %2, V%3, Modus %4</translation>
    </message>
    <message>
        <source>No parameter list for this software version: options cannot be set.</source>
        <translation>Keine Parameterliste für diese Softwareversion: Optionen können nicht gesetzt werden.</translation>
    </message>
    <message>
        <source>This module has no bus options to set.</source>
        <translation>Dieses Modul hat keine Busoptionen zum Setzen.</translation>
    </message>
    <message>
        <source>Options</source>
        <translation>Optionen</translation>
    </message>
    <message>
        <source>Tick an option to write it. Unticked options stay as they are on the module.</source>
        <translation>Kreuzen Sie eine Option an, um sie zu schreiben. Nicht angekreuzte Optionen bleiben im Modul unverändert.</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldPlcPage</name>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation>PDF exportieren</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export HTML</source>
        <translation>HTML exportieren</translation>
    </message>
    <message>
        <source>HTML (*.html)</source>
        <translation>HTML (*.html)</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>CSV exportieren</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Save fold plan</source>
        <translation>Modulplan speichern</translation>
    </message>
    <message>
        <source>Fold plan (*.vtfold)</source>
        <translation>Modulplan (*.vtfold)</translation>
    </message>
    <message>
        <source>fold</source>
        <translation>modulplan</translation>
    </message>
    <message>
        <source>Written: %1</source>
        <translation>Geschrieben: %1</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>%1 kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>PLC configuration</source>
        <translation>SPS-Konfiguration</translation>
    </message>
    <message>
        <source>What the PLC programmer installs and configures. Export it or save the plan.</source>
        <translation>Was der SPS-Programmierer installiert und konfiguriert. Exportieren Sie es oder speichern Sie den Plan.</translation>
    </message>
    <message>
        <source>Export PDF …</source>
        <translation>PDF exportieren …</translation>
    </message>
    <message>
        <source>Export HTML …</source>
        <translation>HTML exportieren …</translation>
    </message>
    <message>
        <source>Export CSV …</source>
        <translation>CSV exportieren …</translation>
    </message>
    <message>
        <source>Save plan …</source>
        <translation>Plan speichern …</translation>
    </message>
</context>
<context>
    <name>vt::ui::FoldWizard</name>
    <message>
        <source>Module fold wizard</source>
        <translation>Knoten-Assistent</translation>
    </message>
    <message>
        <source>&lt; &amp;Back</source>
        <translation>&lt; &amp;Zurück</translation>
    </message>
    <message>
        <source>&amp;Next &gt;</source>
        <translation>&amp;Weiter &gt;</translation>
    </message>
    <message>
        <source>Commit</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>&amp;Finish</source>
        <translation>&amp;Fertigstellen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
</context>
<context>
    <name>vt::ui::FrameDetail</name>
    <message>
        <source>Error at byte %1: %2</source>
        <translation>Fehler bei Byte %1: %2</translation>
    </message>
</context>
<context>
    <name>vt::ui::GuidedPanel</name>
    <message>
        <source>Connect and choose a module and its set value first.</source>
        <translation>Zuerst verbinden und ein Modul und seinen Sollwert wählen.</translation>
    </message>
    <message>
        <source>A test is running; start the guided tuning after it.</source>
        <translation>Ein Test läuft; die geführte Reglereinstellung danach starten.</translation>
    </message>
    <message>
        <source>Choose a step in the signal form: the guided tuning measures its up step (From, To, Hold).</source>
        <translation>Im Signalformular einen Sprung wählen: Die geführte Reglereinstellung misst seinen Sprung nach oben (Von, Bis, Haltezeit).</translation>
    </message>
    <message>
        <source>Guided tuning: up to %1 steps from %2 to %3, each held %4 s; every change of %5 is asked for (or allowed); Abort puts the gains back, and %6 is written back after each step.</source>
        <translation>Geführte Reglereinstellung: bis zu %1 Sprünge von %2 auf %3, je %4 s gehalten; jede Änderung von %5 wird erfragt (oder ist freigegeben); Abbrechen stellt die Verstärkungen wieder her, und %6 wird nach jedem Sprung zurückgeschrieben.</translation>
    </message>
    <message>
        <source>Iteration %1: measuring the step…</source>
        <translation>Durchgang %1: Der Sprung wird gemessen …</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Overshoot at most</source>
        <translation>Überschwingen höchstens</translation>
    </message>
    <message>
        <source>Fastest without overshoot</source>
        <translation>Am schnellsten ohne Überschwingen</translation>
    </message>
    <message>
        <source>Overshoot limit (%)</source>
        <translation>Grenze Überschwingen (%)</translation>
    </message>
    <message>
        <source>Iterations at most</source>
        <translation>Durchgänge höchstens</translation>
    </message>
    <message>
        <source>Allow the next gain changes without asking</source>
        <translation>Die nächsten Änderungen der Verstärkung ohne Rückfrage zulassen</translation>
    </message>
    <message>
        <source>Each iteration runs the up step of the signal form (From, To, Hold), reads the overshoot and proposes the next P gain; the I portion is kept. Keep leaves the chosen gains on the device, Abort puts the original ones back.</source>
        <translation>Jeder Durchgang fährt den Sprung nach oben aus dem Signalformular (Von, Bis, Haltezeit), liest das Überschwingen und schlägt den nächsten P-Anteil vor; der I-Anteil bleibt. Übernehmen lässt die gewählten Verstärkungen im Gerät, Abbrechen stellt die ursprünglichen wieder her.</translation>
    </message>
    <message>
        <source>Start Guided Tuning</source>
        <translation>Geführte Reglereinstellung starten</translation>
    </message>
    <message>
        <source>Keep</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Iteration</source>
        <translation>Durchgang</translation>
    </message>
    <message>
        <source>P gain</source>
        <translation>P-Anteil</translation>
    </message>
    <message>
        <source>I portion</source>
        <translation>I-Anteil</translation>
    </message>
    <message>
        <source>Overshoot (%)</source>
        <translation>Überschwingen (%)</translation>
    </message>
    <message>
        <source>Rise time (s)</source>
        <translation>Anstiegszeit (s)</translation>
    </message>
    <message>
        <source>Settling 2 % (s)</source>
        <translation>Ausregelzeit 2 % (s)</translation>
    </message>
    <message>
        <source>Switch the set-value source for each step and put it back afterwards?</source>
        <translation>Die Sollwertquelle für jeden Sprung umschalten und danach zurückstellen?</translation>
    </message>
</context>
<context>
    <name>vt::ui::HartPage</name>
    <message>
        <source>HART</source>
        <translation>HART</translation>
    </message>
    <message>
        <source>Choose the HART modem&apos;s serial port or type its path.</source>
        <translation>Wählen Sie die serielle Schnittstelle des HART-Modems oder geben Sie ihren Pfad ein.</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>&amp;Port:</translation>
    </message>
    <message>
        <source>Line:</source>
        <translation>Leitung:</translation>
    </message>
    <message>
        <source>%1 baud %2 (fixed by HART)</source>
        <translation>%1 Baud %2 (durch HART festgelegt)</translation>
    </message>
    <message>
        <source>P&amp;oll address:</source>
        <translation>P&amp;olling-Adresse:</translation>
    </message>
    <message>
        <source>0 for a single device on the loop</source>
        <translation>0 für ein einzelnes Gerät in der Stromschleife</translation>
    </message>
</context>
<context>
    <name>vt::ui::HcsProductBox</name>
    <message>
        <source>Tell from the version</source>
        <translation>Aus der Version ermitteln</translation>
    </message>
    <message>
        <source>HCS OPAT</source>
        <translation>HCS OPAT</translation>
    </message>
    <message>
        <source>HCS DMA-2 PROFINET</source>
        <translation>HCS DMA-2 PROFINET</translation>
    </message>
    <message>
        <source>HCS DMA-2 PROFIBUS</source>
        <translation>HCS DMA-2 PROFIBUS</translation>
    </message>
</context>
<context>
    <name>vt::ui::InspectorView</name>
    <message>
        <source>Go to parameter %1</source>
        <translation>Zu Parameter %1 wechseln</translation>
    </message>
    <message>
        <source>Decode a copy</source>
        <translation>Kopie dekodieren</translation>
    </message>
    <message>
        <source>Save telegrams as CSV</source>
        <translation>Telegramme als CSV speichern</translation>
    </message>
    <message>
        <source>Save telegrams as text</source>
        <translation>Telegramme als Text speichern</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Text files (*.txt)</source>
        <translation>Textdateien (*.txt)</translation>
    </message>
    <message>
        <source>Save failed</source>
        <translation>Speichern fehlgeschlagen</translation>
    </message>
    <message>
        <source>Could not save %1: %2</source>
        <translation>%1 konnte nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <source>Module:</source>
        <translation>Modul:</translation>
    </message>
    <message>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <source>Protocol:</source>
        <translation>Protokoll:</translation>
    </message>
    <message>
        <source>Errors only</source>
        <translation>Nur Fehler</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Freezes the list; frames are still recorded and appear when resumed.</source>
        <translation>Hält die Liste an; Telegramme werden weiter aufgezeichnet und erscheinen beim Fortsetzen.</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Save CSV…</source>
        <translation>CSV speichern…</translation>
    </message>
    <message>
        <source>Save text…</source>
        <translation>Text speichern…</translation>
    </message>
    <message>
        <source>Go to parameter</source>
        <translation>Zum Parameter</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Telegramm</translation>
    </message>
    <message>
        <source>Decode</source>
        <translation>Dekodieren</translation>
    </message>
    <message>
        <source>Compose</source>
        <translation>Erstellen</translation>
    </message>
</context>
<context>
    <name>vt::ui::LCurveEditor</name>
    <message>
        <source>Drag a point or type its coordinates. Input x must rise from point to point; grey coordinates are fixed by the device. Whether the module applies the curve depends on the branch&apos;s Linearization parameter (C1.02 / C2.02).</source>
        <translation>Ziehen Sie einen Punkt oder geben Sie seine Koordinaten ein. Der Eingang x muss von Punkt zu Punkt steigen; graue Koordinaten sind vom Gerät vorgegeben. Ob das Modul die Kennlinie anwendet, hängt vom Parameter Linearisierung des Zweigs ab (C1.02 / C2.02).</translation>
    </message>
    <message>
        <source>This device has no linearisation curve: the parameter list of %1 has no L block.</source>
        <translation>Dieses Gerät hat keine Linearisierungskurve: die Parameterliste von %1 hat keinen L-Block.</translation>
    </message>
    <message>
        <source>No module chosen: choose one in the node view.</source>
        <translation>Kein Modul gewählt: Wählen Sie eines in der Knotenansicht.</translation>
    </message>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message>
        <source>Module %1: %2</source>
        <translation>Modul %1: %2</translation>
    </message>
</context>
<context>
    <name>vt::ui::LCurvePlot</name>
    <message>
        <source>Input (set value)</source>
        <translation>Eingang (Sollwert)</translation>
    </message>
    <message>
        <source>Input (set value) / %1</source>
        <translation>Eingang (Sollwert) / %1</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Output / %1</source>
        <translation>Ausgang / %1</translation>
    </message>
    <message>
        <source>Branch %1 (%2)</source>
        <translation>Zweig %1 (%2)</translation>
    </message>
</context>
<context>
    <name>vt::ui::LinkStatusWidget</name>
    <message>
        <source>%1, V%2</source>
        <translation>%1, V%2</translation>
    </message>
    <message>
        <source>%1, mode %2</source>
        <translation>%1, Modus %2</translation>
    </message>
    <message>
        <source>#%1 %2</source>
        <translation>#%1 %2</translation>
    </message>
    <message>
        <source>%1 (nearest match)</source>
        <translation>%1 (nächste Übereinstimmung)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>requests %1 · retries %2 · timeouts %3 · refused %4 · failed %5</source>
        <translation>Anfragen %1 · Wiederholungen %2 · Zeitüberschreitungen %3 · abgelehnt %4 · fehlgeschlagen %5</translation>
    </message>
    <message>
        <source>Frames sent: %1. Refused: the device answered with an exception. Failed: no answer after every retry, or the link was lost.</source>
        <translation>Gesendete Telegramme: %1. Abgelehnt: Das Gerät hat mit einer Ausnahme geantwortet. Fehlgeschlagen: keine Antwort nach allen Wiederholungen, oder die Verbindung ist abgerissen.</translation>
    </message>
</context>
<context>
    <name>vt::ui::MapReportDialog</name>
    <message>
        <source>What Did Not Map</source>
        <translation>Nicht zugeordnete Werte</translation>
    </message>
    <message>
        <source>Module %1 (%2): %3</source>
        <translation>Modul %1 (%2): %3</translation>
    </message>
    <message numerus="yes">
        <source>Module %1: family &quot;%2&quot; is not known to this version; its %n value(s) are kept and saved unchanged.</source>
        <translation>
            <numerusform>Modul %1: Die Familie &quot;%2&quot; ist dieser Version nicht bekannt; der %n Wert des Moduls wird beibehalten und unverändert gespeichert.</numerusform>
            <numerusform>Modul %1: Die Familie &quot;%2&quot; ist dieser Version nicht bekannt; die %n Werte des Moduls werden beibehalten und unverändert gespeichert.</numerusform>
        </translation>
    </message>
    <message>
        <source>Rows that did not map are kept in the file and written back unchanged on save.</source>
        <translation>Nicht zugeordnete Zeilen bleiben in der Datei erhalten und werden beim Speichern unverändert zurückgeschrieben.</translation>
    </message>
    <message>
        <source>With the connected node:</source>
        <translation>Mit dem verbundenen Knoten:</translation>
    </message>
</context>
<context>
    <name>vt::ui::MonitorPlot</name>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>module %1 (%2 %3)</source>
        <translation>Modul %1 (%2 %3)</translation>
    </message>
    <message>
        <source>ValveTune monitor, %1</source>
        <translation>ValveTune-Monitor, %1</translation>
    </message>
    <message>
        <source>ValveTune monitor: %1, %2</source>
        <translation>ValveTune-Monitor: %1, %2</translation>
    </message>
</context>
<context>
    <name>vt::ui::MonitorView</name>
    <message>
        <source>Monitor, module %1: %2</source>
        <translation>Monitor, Modul %1: %2</translation>
    </message>
    <message>
        <source>achieved: –</source>
        <translation>erreicht: –</translation>
    </message>
    <message>
        <source>%1: %2 Hz</source>
        <translation>%1: %2 Hz</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>achieved: %1</source>
        <translation>erreicht: %1</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-Dateien (*.pdf)</translation>
    </message>
    <message>
        <source>Export monitor</source>
        <translation>Monitor exportieren</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>Exportiert nach %1</translation>
    </message>
    <message>
        <source>Export to %1 failed: %2</source>
        <translation>Export nach %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>could not write the file</source>
        <translation>die Datei konnte nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>Rate:</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>as fast as the link allows</source>
        <translation>so schnell die Verbindung erlaubt</translation>
    </message>
    <message>
        <source>Polls per second and module; the lowest value polls back to back, as fast as the link allows.</source>
        <translation>Abfragen je Sekunde und Modul; der kleinste Wert fragt ohne Pause ab, so schnell die Verbindung erlaubt.</translation>
    </message>
    <message>
        <source>Window:</source>
        <translation>Fenster:</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>Folgen</translation>
    </message>
    <message>
        <source>Keep the newest samples in view. Dragging or zooming the time axis turns this off.</source>
        <translation>Die neuesten Messwerte im Blick behalten. Ziehen oder Zoomen der Zeitachse schaltet dies aus.</translation>
    </message>
    <message>
        <source>Channels…</source>
        <translation>Kanäle…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <source>Visible range as CSV…</source>
        <translation>Sichtbarer Bereich als CSV…</translation>
    </message>
    <message>
        <source>Everything as CSV…</source>
        <translation>Alles als CSV…</translation>
    </message>
    <message>
        <source>Plot as PNG…</source>
        <translation>Diagramm als PNG…</translation>
    </message>
    <message>
        <source>Plot as PDF…</source>
        <translation>Diagramm als PDF…</translation>
    </message>
    <message>
        <source>Nothing to monitor: the parameter list of this module names no default channels. Choose the values to plot with Channels….</source>
        <translation>Nichts zu beobachten: die Parameterliste dieses Moduls nennt keine Standardkanäle. Wählen Sie die Werte für die Darstellung mit Kanäle….</translation>
    </message>
</context>
<context>
    <name>vt::ui::NewFileDialog</name>
    <message>
        <source>This combination cannot be a device.</source>
        <translation>Diese Kombination ergibt kein gültiges Gerät.</translation>
    </message>
    <message>
        <source>address %1</source>
        <translation>Adresse %1</translation>
    </message>
    <message>
        <source>address %1 (V%2)</source>
        <translation>Adresse %1 (V%2)</translation>
    </message>
    <message numerus="yes">
        <source>%n module(s): %1. Values start at the dictionary&apos;s defaults.</source>
        <translation>
            <numerusform>%n Modul: %1. Die Werte beginnen bei den Vorgabewerten des Wörterbuchs.</numerusform>
            <numerusform>%n Module: %1. Die Werte beginnen bei den Vorgabewerten des Wörterbuchs.</numerusform>
        </translation>
    </message>
    <message>
        <source>New parameter file</source>
        <translation>Neue Parameterdatei</translation>
    </message>
    <message>
        <source>&amp;Device family:</source>
        <translation>&amp;Gerätefamilie:</translation>
    </message>
    <message>
        <source>Software &amp;version:</source>
        <translation>Software&amp;version:</translation>
    </message>
    <message>
        <source>&amp;Mode:</source>
        <translation>&amp;Modus:</translation>
    </message>
    <message>
        <source>M&amp;odules:</source>
        <translation>M&amp;odule:</translation>
    </message>
    <message>
        <source>V%1</source>
        <translation>V%1</translation>
    </message>
    <message>
        <source>identified from the device</source>
        <translation>vom Gerät ermittelt</translation>
    </message>
</context>
<context>
    <name>vt::ui::NodeView</name>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message>
        <source>online</source>
        <translation>online</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>offline</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Version</source>
        <translation>Version</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>State word</source>
        <translation>Statuswort</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>(not read)</source>
        <translation>(nicht gelesen)</translation>
    </message>
    <message>
        <source>Device state</source>
        <translation>Gerätezustand</translation>
    </message>
    <message>
        <source>Device state (db_ControlWord)</source>
        <translation>Gerätezustand (db_ControlWord)</translation>
    </message>
    <message>
        <source>%1 (control word 0x%2)</source>
        <translation>%1 (Steuerwort 0x%2)</translation>
    </message>
    <message>
        <source>Reset fault</source>
        <translation>Fehler quittieren</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Device local and device mode change only in INIT or DISABLED; the device is in %1.</source>
        <translation>Steuerhoheit (Device local) und Sollwertvorgabe (Device mode) lassen sich nur in INIT oder DISABLED ändern; das Gerät ist in %1.</translation>
    </message>
</context>
<context>
    <name>vt::ui::ParameterEditor</name>
    <message>
        <source>Search name or text…</source>
        <translation>Name oder Text suchen…</translation>
    </message>
    <message>
        <source>Changed only</source>
        <translation>Nur geänderte</translation>
    </message>
    <message>
        <source>Differs from device</source>
        <translation>Abweichend vom Gerät</translation>
    </message>
    <message>
        <source>Show inactive</source>
        <translation>Inaktive anzeigen</translation>
    </message>
    <message>
        <source>Show Telegrams of This Parameter</source>
        <translation>Telegramme dieses Parameters anzeigen</translation>
    </message>
    <message>
        <source>Help on This Parameter</source>
        <translation>Hilfe zu diesem Parameter</translation>
    </message>
</context>
<context>
    <name>vt::ui::ReferenceDriftView</name>
    <message>
        <source>step up</source>
        <translation>Sprung aufwärts</translation>
    </message>
    <message>
        <source>step down</source>
        <translation>Sprung abwärts</translation>
    </message>
    <message>
        <source>sweep</source>
        <translation>Sweep</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Sprünge</translation>
    </message>
    <message>
        <source>rise time 10–90 %</source>
        <translation>Anstiegszeit 10–90 %</translation>
    </message>
    <message>
        <source>overshoot</source>
        <translation>Überschwingen</translation>
    </message>
    <message>
        <source>settling time 2 %</source>
        <translation>Ausregelzeit 2 %</translation>
    </message>
    <message>
        <source>steady-state error</source>
        <translation>bleibende Regelabweichung</translation>
    </message>
    <message>
        <source>bandwidth (−3 dB)</source>
        <translation>Bandbreite (−3 dB)</translation>
    </message>
    <message>
        <source>frequency at −90°</source>
        <translation>Frequenz bei −90°</translation>
    </message>
    <message>
        <source>No reference yet: save one, or compare the module with one.</source>
        <translation>Noch keine Referenz: speichern Sie eine, oder vergleichen Sie das Modul mit einer.</translation>
    </message>
    <message>
        <source>Reference of module %1 (%2, software %3, mode %4), %5 settings.</source>
        <translation>Referenz von Modul %1 (%2, Software %3, Modus %4), %5 Einstellungen.</translation>
    </message>
    <message>
        <source>%1 of %2 figures drifted beyond their thresholds.</source>
        <translation>%1 von %2 Kennwerten sind über ihre Schwellen hinaus abgewichen.</translation>
    </message>
    <message>
        <source>All %1 figures are within their thresholds.</source>
        <translation>Alle %1 Kennwerte liegen innerhalb ihrer Schwellen.</translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) differ from the reference.</source>
        <translation>
            <numerusform>%n Einstellung weicht von der Referenz ab.</numerusform>
            <numerusform>%n Einstellungen weichen von der Referenz ab.</numerusform>
        </translation>
    </message>
    <message>
        <source>Test</source>
        <translation>Test</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>Kennwert</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>Now</source>
        <translation>Jetzt</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>%1 Pkt.</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1%2 points</source>
        <translation>%1%2 Pkt.</translation>
    </message>
    <message>
        <source>%1%2 %</source>
        <translation>%1%2 %</translation>
    </message>
    <message>
        <source> of the step</source>
        <translation> des Sprungs</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>exceeded</source>
        <translation>überschritten</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>now</source>
        <translation>jetzt</translation>
    </message>
    <message>
        <source>reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>Change (limit)</source>
        <translation>Änderung (Grenze)</translation>
    </message>
</context>
<context>
    <name>vt::ui::ReferencePanel</name>
    <message>
        <source>Save as Reference</source>
        <translation>Als Referenz speichern</translation>
    </message>
    <message>
        <source>ValveTune references (*.vtref)</source>
        <translation>ValveTune-Referenzen (*.vtref)</translation>
    </message>
    <message>
        <source>Compare with Reference</source>
        <translation>Mit Referenz vergleichen</translation>
    </message>
    <message>
        <source>Connect and choose a module and its set value first.</source>
        <translation>Verbinden Sie zuerst und wählen Sie ein Modul und seinen Sollwert.</translation>
    </message>
    <message>
        <source>This reference does not fit: %1</source>
        <translation>Diese Referenz passt nicht: %1</translation>
    </message>
    <message>
        <source>A test is running; start the reference tests after it.</source>
        <translation>Ein Test läuft; starten Sie die Referenztests danach.</translation>
    </message>
    <message>
        <source>a stepped-sine sweep from %1 to %2 Hz</source>
        <translation>ein Sinus-Sweep in Stufen von %1 bis %2 Hz</translation>
    </message>
    <message>
        <source>a step up and a step down, each level held %1 s</source>
        <translation>ein Sprung aufwärts und ein Sprung abwärts, jede Stufe %1 s gehalten</translation>
    </message>
    <message>
        <source>Reference tests: %1; between %2 and %3, about %4 s in all; afterwards %5 is written back.</source>
        <translation>Referenztests: %1; zwischen %2 und %3, insgesamt etwa %4 s; danach wird %5 zurückgeschrieben.</translation>
    </message>
    <message>
        <source> and </source>
        <translation> und </translation>
    </message>
    <message>
        <source>For the tests only: afterwards the values are written back.</source>
        <translation>Nur für die Tests: danach werden die Werte zurückgeschrieben.</translation>
    </message>
    <message>
        <source>Reference saved to %1: %2 settings, %3 test(s); the set value is restored.</source>
        <translation>Referenz in %1 gespeichert: %2 Einstellungen, %3 Test(s); der Sollwert ist wiederhergestellt.</translation>
    </message>
    <message>
        <source>Compared with %1; the set value is restored.</source>
        <translation>Mit %1 verglichen; der Sollwert ist wiederhergestellt.</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>Mitte</translation>
    </message>
    <message>
        <source>The set value the tests move around.</source>
        <translation>Der Sollwert, um den sich die Tests bewegen.</translation>
    </message>
    <message>
        <source>Amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <source>The steps go from centre − amplitude to centre + amplitude and back; the sweep swings by ± amplitude.</source>
        <translation>Die Sprünge gehen von Mitte − Amplitude nach Mitte + Amplitude und zurück; der Sweep schwingt um ± Amplitude.</translation>
    </message>
    <message>
        <source>Hold (s)</source>
        <translation>Haltezeit (s)</translation>
    </message>
    <message>
        <source>How long each level of the steps is held: several settling times.</source>
        <translation>Wie lange jede Stufe der Sprünge gehalten wird: mehrere Ausregelzeiten.</translation>
    </message>
    <message>
        <source>Also a stepped-sine sweep</source>
        <translation>Zusätzlich ein Sinus-Sweep in Stufen</translation>
    </message>
    <message>
        <source>Sweep from (Hz)</source>
        <translation>Sweep von (Hz)</translation>
    </message>
    <message>
        <source>Sweep to (Hz)</source>
        <translation>Sweep bis (Hz)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Drift thresholds&lt;/b&gt;</source>
        <translation>&lt;b&gt;Schwellen für Abweichungen&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Rise time ± (%)</source>
        <translation>Anstiegszeit ± (%)</translation>
    </message>
    <message>
        <source>Overshoot + (points)</source>
        <translation>Überschwingen + (Prozentpunkte)</translation>
    </message>
    <message>
        <source>Settling time ± (%)</source>
        <translation>Ausregelzeit ± (%)</translation>
    </message>
    <message>
        <source>Steady-state error ± (% of the step)</source>
        <translation>Bleibende Regelabweichung ± (% des Sprungs)</translation>
    </message>
    <message>
        <source>Bandwidth ± (%)</source>
        <translation>Bandbreite ± (%)</translation>
    </message>
    <message>
        <source>−90° frequency ± (%)</source>
        <translation>Frequenz bei −90° ± (%)</translation>
    </message>
    <message>
        <source>Save as Reference…</source>
        <translation>Als Referenz speichern…</translation>
    </message>
    <message>
        <source>Compare with Reference…</source>
        <translation>Mit Referenz vergleichen…</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>A reference keeps the module&apos;s settings and its responses to these tests in one file; comparing repeats the tests.</source>
        <translation>Eine Referenz hält die Einstellungen des Moduls und seine Antworten auf diese Tests in einer Datei fest; ein Vergleich wiederholt die Tests.</translation>
    </message>
</context>
<context>
    <name>vt::ui::ReportDialog</name>
    <message>
        <source>Commissioning Report</source>
        <translation>Inbetriebnahmeprotokoll</translation>
    </message>
    <message>
        <source>No workbench runs in this session.</source>
        <translation>Keine Werkbank-Läufe in dieser Sitzung.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Reference parameter file</source>
        <translation>Referenz-Parameterdatei</translation>
    </message>
    <message>
        <source>Parameter files (*.vtpar)</source>
        <translation>Parameterdateien (*.vtpar)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <source>HTML page (*.html)</source>
        <translation>HTML-Seite (*.html)</translation>
    </message>
    <message>
        <source>JSON data (*.json)</source>
        <translation>JSON-Daten (*.json)</translation>
    </message>
    <message>
        <source>Customer:</source>
        <translation>Kunde:</translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation>Maschine:</translation>
    </message>
    <message>
        <source>Axis:</source>
        <translation>Achse:</translation>
    </message>
    <message>
        <source>Operator:</source>
        <translation>Bearbeiter:</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Bemerkung:</translation>
    </message>
    <message>
        <source>Workbench runs:</source>
        <translation>Werkbank-Läufe:</translation>
    </message>
    <message>
        <source>Reference file:</source>
        <translation>Referenzdatei:</translation>
    </message>
    <message>
        <source>Language:</source>
        <translation>Sprache:</translation>
    </message>
    <message>
        <source>Format:</source>
        <translation>Format:</translation>
    </message>
    <message>
        <source>Print Preview…</source>
        <translation>Druckvorschau…</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <source>Save Commissioning Report</source>
        <translation>Inbetriebnahmeprotokoll speichern</translation>
    </message>
    <message>
        <source>commissioning-report.%1</source>
        <translation>inbetriebnahmeprotokoll.%1</translation>
    </message>
    <message>
        <source>Drift against the reference fingerprint %1</source>
        <translation>Drift gegenüber dem Referenz-Fingerabdruck %1</translation>
    </message>
</context>
<context>
    <name>vt::ui::ResponsePlot</name>
    <message>
        <source>run %1: </source>
        <translation>Lauf %1: </translation>
    </message>
    <message>
        <source>%1 written</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>10 %</source>
        <translation>10 %</translation>
    </message>
    <message>
        <source>90 %</source>
        <translation>90 %</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
</context>
<context>
    <name>vt::ui::RunList</name>
    <message>
        <source>Save Run</source>
        <translation>Lauf speichern</translation>
    </message>
    <message>
        <source>run-%1.csv</source>
        <translation>lauf-%1.csv</translation>
    </message>
    <message>
        <source>Run recordings (*.csv)</source>
        <translation>Laufaufzeichnungen (*.csv)</translation>
    </message>
    <message>
        <source>Saved %1 and its .json.</source>
        <translation>%1 und die zugehörige .json gespeichert.</translation>
    </message>
    <message>
        <source>Load Runs</source>
        <translation>Läufe laden</translation>
    </message>
    <message>
        <source>Runs (*.json *.csv)</source>
        <translation>Läufe (*.json *.csv)</translation>
    </message>
    <message>
        <source>Runs</source>
        <translation>Läufe</translation>
    </message>
    <message>
        <source>Save Run…</source>
        <translation>Lauf speichern …</translation>
    </message>
    <message>
        <source>Load Runs…</source>
        <translation>Läufe laden …</translation>
    </message>
    <message>
        <source>The current run is drawn with its marks; tick others to overlay them and to compare their settings.</source>
        <translation>Der aktuelle Lauf wird mit seinen Markierungen gezeichnet; weitere ankreuzen, um sie zu überlagern und ihre Einstellungen zu vergleichen.</translation>
    </message>
</context>
<context>
    <name>vt::ui::RunResultsTabs</name>
    <message>
        <source>No response row was recorded: nothing to analyse.</source>
        <translation>Keine Antwortzeile aufgezeichnet: nichts auszuwerten.</translation>
    </message>
    <message>
        <source>Frequency (Hz)</source>
        <translation>Frequenz (Hz)</translation>
    </message>
    <message>
        <source>Gain (dB)</source>
        <translation>Verstärkung (dB)</translation>
    </message>
    <message>
        <source>Phase (°)</source>
        <translation>Phase (°)</translation>
    </message>
    <message>
        <source>Quality</source>
        <translation>Güte</translation>
    </message>
    <message>
        <source>Valid</source>
        <translation>Gültig</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>−3 dB at</source>
        <translation>−3 dB bei</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>nicht erreicht</translation>
    </message>
    <message>
        <source>−90° at</source>
        <translation>−90° bei</translation>
    </message>
    <message>
        <source>Step (%1)</source>
        <translation>Sprung (%1)</translation>
    </message>
    <message>
        <source>Dead time (s)</source>
        <translation>Totzeit (s)</translation>
    </message>
    <message>
        <source>Rise time (s)</source>
        <translation>Anstiegszeit (s)</translation>
    </message>
    <message>
        <source>Overshoot (%)</source>
        <translation>Überschwingen (%)</translation>
    </message>
    <message>
        <source>Peak time (s)</source>
        <translation>Spitzenzeit (s)</translation>
    </message>
    <message>
        <source>Settling 2 % (s)</source>
        <translation>Ausregelzeit 2 % (s)</translation>
    </message>
    <message>
        <source>Settling 5 % (s)</source>
        <translation>Ausregelzeit 5 % (s)</translation>
    </message>
    <message>
        <source>Steady-state error (%1)</source>
        <translation>Bleibende Regelabweichung (%1)</translation>
    </message>
    <message>
        <source>Final value</source>
        <translation>Endwert</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Tick a second run to compare its settings</source>
        <translation>Einen zweiten Lauf ankreuzen, um seine Einstellungen zu vergleichen</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Run %1</source>
        <translation>Lauf %1</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>Ergebnisse</translation>
    </message>
    <message>
        <source>Setting differences</source>
        <translation>Unterschiede der Einstellungen</translation>
    </message>
</context>
<context>
    <name>vt::ui::SerialLineFields</name>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>&amp;Baudrate:</translation>
    </message>
    <message>
        <source>&amp;Data bits:</source>
        <translation>Da&amp;tenbits:</translation>
    </message>
    <message>
        <source>Pa&amp;rity:</source>
        <translation>Pa&amp;rität:</translation>
    </message>
    <message>
        <source>&amp;Stop bits:</source>
        <translation>&amp;Stoppbits:</translation>
    </message>
    <message>
        <source>None (N)</source>
        <translation>Keine (N)</translation>
    </message>
    <message>
        <source>Even (E)</source>
        <translation>Gerade (E)</translation>
    </message>
    <message>
        <source>Odd (O)</source>
        <translation>Ungerade (O)</translation>
    </message>
    <message>
        <source>Baud rate: %1</source>
        <translation>Baudrate: %1</translation>
    </message>
</context>
<context>
    <name>vt::ui::SerialPage</name>
    <message>
        <source>Serial (Modbus RTU)</source>
        <translation>Seriell (Modbus RTU)</translation>
    </message>
    <message>
        <source>Choose a serial port or type its path.</source>
        <translation>Wählen Sie eine serielle Schnittstelle oder geben Sie ihren Pfad ein.</translation>
    </message>
    <message>
        <source>Module address 0 is the Modbus broadcast address, which no module answers; use 1..%1.</source>
        <translation>Moduladresse 0 ist die Modbus-Broadcast-Adresse, auf die kein Modul antwortet; verwenden Sie 1..%1.</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>&amp;Port:</translation>
    </message>
    <message>
        <source>Module &amp;address:</source>
        <translation>Modul&amp;adresse:</translation>
    </message>
    <message>
        <source>Modbus unit: the module&apos;s address on an RS485 line (E22, DIP switches); 1 on a point-to-point line</source>
        <translation>Modbus-Unit: die Adresse des Moduls an einer RS485-Leitung (E22, DIP-Schalter); 1 bei einer Punkt-zu-Punkt-Verbindung</translation>
    </message>
    <message>
        <source>Pro&amp;duct:</source>
        <translation>Pro&amp;dukt:</translation>
    </message>
</context>
<context>
    <name>vt::ui::SerialPortBox</name>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>List the serial ports again</source>
        <translation>Serielle Schnittstellen neu auflisten</translation>
    </message>
    <message>
        <source>/dev/ttyUSB0</source>
        <translation>/dev/ttyUSB0</translation>
    </message>
</context>
<context>
    <name>vt::ui::SignalForm</name>
    <message>
        <source>Step</source>
        <translation>Sprung</translation>
    </message>
    <message>
        <source>Square</source>
        <translation>Rechteck</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation>Dreieck</translation>
    </message>
    <message>
        <source>Sine</source>
        <translation>Sinus</translation>
    </message>
    <message>
        <source>Stepped-sine sweep</source>
        <translation>Sinus-Sweep in Stufen</translation>
    </message>
    <message>
        <source>up (from → to)</source>
        <translation>aufwärts (von → bis)</translation>
    </message>
    <message>
        <source>down (to → from)</source>
        <translation>abwärts (bis → von)</translation>
    </message>
    <message>
        <source>both (from → to → from)</source>
        <translation>beide (von → bis → von)</translation>
    </message>
    <message>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Von</translation>
    </message>
    <message>
        <source>To</source>
        <translation>Bis</translation>
    </message>
    <message>
        <source>Hold (s)</source>
        <translation>Haltezeit (s)</translation>
    </message>
    <message>
        <source>Repeats</source>
        <translation>Wiederholungen</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>Frequency (Hz)</source>
        <translation>Frequenz (Hz)</translation>
    </message>
    <message>
        <source>Measured cycles</source>
        <translation>Gemessene Perioden</translation>
    </message>
    <message>
        <source>Settling cycles</source>
        <translation>Einschwingperioden</translation>
    </message>
    <message>
        <source>From (Hz)</source>
        <translation>Von (Hz)</translation>
    </message>
    <message>
        <source>To (Hz)</source>
        <translation>Bis (Hz)</translation>
    </message>
    <message>
        <source>Points per decade</source>
        <translation>Punkte je Dekade</translation>
    </message>
    <message>
        <source>Cycles per point</source>
        <translation>Perioden je Punkt</translation>
    </message>
</context>
<context>
    <name>vt::ui::SimPage</name>
    <message>
        <source>Simulator</source>
        <translation>Simulator</translation>
    </message>
    <message>
        <source>No device family can be simulated: the dictionaries did not load.</source>
        <translation>Keine Gerätefamilie kann simuliert werden: Die Wörterbücher wurden nicht geladen.</translation>
    </message>
    <message>
        <source>Over Modbus RTU the OPAT master (address 0) is the broadcast address and cannot answer; choose Modbus TCP or the node image for a node with slaves.</source>
        <translation>Über Modbus RTU ist der OPAT-Master (Adresse 0) die Broadcast-Adresse und kann nicht antworten; wählen Sie Modbus TCP oder das Knotenabbild für einen Knoten mit Slaves.</translation>
    </message>
    <message>
        <source>&amp;Family:</source>
        <translation>&amp;Familie:</translation>
    </message>
    <message>
        <source>&amp;Mode:</source>
        <translation>&amp;Modus:</translation>
    </message>
    <message>
        <source>M&amp;odules:</source>
        <translation>M&amp;odule:</translation>
    </message>
    <message>
        <source>Modules of the node: an OPAT master and its CAN slaves, or DMA-2 modules with addresses 1, 2, 3 …</source>
        <translation>Module des Knotens: ein OPAT-Master und seine CAN-Slaves oder DMA-2-Module mit den Adressen 1, 2, 3 …</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protokoll:</translation>
    </message>
    <message>
        <source>not chosen at start-up</source>
        <translation>beim Start nicht gewählt</translation>
    </message>
    <message>
        <source>Automatic (Modbus RTU for one module, Modbus TCP for a node)</source>
        <translation>Automatisch (Modbus RTU für ein Modul, Modbus TCP für einen Knoten)</translation>
    </message>
    <message>
        <source>Modbus RTU</source>
        <translation>Modbus RTU</translation>
    </message>
    <message>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <source>Node image (cyclic telegrams, CMD 3/6/15)</source>
        <translation>Knotenabbild (zyklische Telegramme, CMD 3/6/15)</translation>
    </message>
    <message>
        <source>HART</source>
        <translation>HART</translation>
    </message>
    <message>
        <source>PROFIBUS image (PKW + PZD, cyclic)</source>
        <translation>PROFIBUS-Abbild (PKW + PZD, zyklisch)</translation>
    </message>
    <message>
        <source>PROFIBUS gateway (Modbus TCP registers)</source>
        <translation>PROFIBUS-Gateway (Modbus-TCP-Register)</translation>
    </message>
</context>
<context>
    <name>vt::ui::StepControl</name>
    <message>
        <source>Step:</source>
        <translation>Sprung:</translation>
    </message>
    <message>
        <source>Write step</source>
        <translation>Sprung schreiben</translation>
    </message>
    <message>
        <source>Module %1: %2 (%3), every step until disconnect, without asking again</source>
        <translation>Modul %1: %2 (%3), jeder Sprung bis zum Trennen, ohne erneute Nachfrage</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Scharf</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Scharf schalten</translation>
    </message>
    <message>
        <source>Steps are written without asking until you disarm or disconnect. Click to disarm.</source>
        <translation>Sprünge werden ohne Nachfrage geschrieben, bis Sie entschärfen oder trennen. Klicken zum Entschärfen.</translation>
    </message>
    <message>
        <source>Arm the step: after one confirmation, steps are written without asking again until disconnect.</source>
        <translation>Sprung scharf schalten: nach einer Bestätigung werden Sprünge bis zum Trennen ohne erneute Nachfrage geschrieben.</translation>
    </message>
    <message>
        <source>Module %1: %2</source>
        <translation>Modul %1: %2</translation>
    </message>
    <message>
        <source>No connected module has a bus set value; the step is not available.</source>
        <translation>Kein verbundenes Modul hat einen Bus-Sollwert; der Sprung ist nicht verfügbar.</translation>
    </message>
    <message>
        <source>Writing %1 …</source>
        <translation>%1 wird geschrieben …</translation>
    </message>
    <message>
        <source>Checking %1, then writing %2 …</source>
        <translation>%1 wird geprüft, dann wird %2 geschrieben …</translation>
    </message>
    <message>
        <source>Writing %1 = %2 …</source>
        <translation>%1 = %2 wird geschrieben …</translation>
    </message>
    <message>
        <source>Writes the bus set value (range-checked, read back) and marks it on the time axis, after checking that the module takes its set value from the bus.</source>
        <translation>Schreibt den Bus-Sollwert (Bereich geprüft, zurückgelesen) und markiert ihn auf der Zeitachse, nachdem geprüft wurde, dass das Modul seinen Sollwert vom Bus nimmt.</translation>
    </message>
    <message>
        <source>Set %1 = %2</source>
        <translation>%1 = %2 setzen</translation>
    </message>
    <message>
        <source>Makes the bus set value the one that drives the valve (%1 = %2).</source>
        <translation>Macht den Bus-Sollwert zu dem, der das Ventil steuert (%1 = %2).</translation>
    </message>
    <message>
        <source>Module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message>
        <source>(typed %1, rounded to the device resolution)</source>
        <translation>(eingegeben %1, auf die Auflösung des Geräts gerundet)</translation>
    </message>
    <message>
        <source>%1 → %2 (device resolution)</source>
        <translation>%1 → %2 (Auflösung des Geräts)</translation>
    </message>
    <message>
        <source>Switch to %1 (%2 = %3)</source>
        <translation>In %1 schalten (%2 = %3)</translation>
    </message>
</context>
<context>
    <name>vt::ui::TcpPage</name>
    <message>
        <source>TCP</source>
        <translation>TCP</translation>
    </message>
    <message>
        <source>Type the host name or IP address of the gateway.</source>
        <translation>Geben Sie den Hostnamen oder die IP-Adresse des Gateways ein.</translation>
    </message>
    <message>
        <source>A host name has no spaces: &quot;%1&quot;.</source>
        <translation>Ein Hostname enthält keine Leerzeichen: &quot;%1&quot;.</translation>
    </message>
    <message>
        <source>Port 0 cannot be connected to; Modbus TCP uses %1.</source>
        <translation>Mit Port 0 ist keine Verbindung möglich; Modbus TCP verwendet %1.</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Host:</translation>
    </message>
    <message>
        <source>192.168.0.10 or gateway.local</source>
        <translation>192.168.0.10 oder gateway.local</translation>
    </message>
    <message>
        <source>P&amp;ort:</source>
        <translation>P&amp;ort:</translation>
    </message>
    <message>
        <source>P&amp;rotocol:</source>
        <translation>P&amp;rotokoll:</translation>
    </message>
    <message>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <source>Node image (cyclic telegrams, CMD 3/6/15)</source>
        <translation>Knotenabbild (zyklische Telegramme, CMD 3/6/15)</translation>
    </message>
    <message>
        <source>Module &amp;address:</source>
        <translation>Modul&amp;adresse:</translation>
    </message>
    <message>
        <source>Pro&amp;duct:</source>
        <translation>Pro&amp;dukt:</translation>
    </message>
    <message>
        <source>Wandfluh ED1: PROFIBUS gateway (Modbus TCP registers)</source>
        <translation>Wandfluh ED1: PROFIBUS-Gateway (Modbus-TCP-Register)</translation>
    </message>
    <message>
        <source>Wandfluh ED1: PROFIBUS image (PKW + PZD, cyclic)</source>
        <translation>Wandfluh ED1: PROFIBUS-Abbild (PKW + PZD, zyklisch)</translation>
    </message>
    <message>
        <source>Modbus unit / SADR of the module; 0 is the OPAT master; for the ED1&apos;s gateway its Modbus unit</source>
        <translation>Modbus-Unit / SADR des Moduls; 0 ist der OPAT-Master; beim Gateway der ED1 dessen Modbus-Unit</translation>
    </message>
</context>
<context>
    <name>vt::ui::UserGuideDialog</name>
    <message>
        <source>ValveTune User Guide</source>
        <translation>ValveTune-Benutzerhandbuch</translation>
    </message>
</context>
<context>
    <name>vt::ui::WorkbenchView</name>
    <message>
        <source>Guided tuning</source>
        <translation>Geführte Reglereinstellung</translation>
    </message>
    <message>
        <source>Module %1 (%2)</source>
        <translation>Modul %1 (%2)</translation>
    </message>
    <message>
        <source>Response: %1</source>
        <translation>Antwort: %1</translation>
    </message>
    <message>
        <source>The dictionary names no response for %1: the test records, but has nothing to analyse.</source>
        <translation>Das Wörterbuch nennt keine Antwort für %1: der Test zeichnet auf, hat aber nichts auszuwerten.</translation>
    </message>
    <message>
        <source>No module with a set value a test can drive.</source>
        <translation>Kein Modul mit einem Sollwert, den ein Test vorgeben kann.</translation>
    </message>
    <message>
        <source>Connect to a device to run a test.</source>
        <translation>Verbinden Sie ein Gerät, um einen Test zu fahren.</translation>
    </message>
    <message>
        <source>A step needs different From and To values.</source>
        <translation>Ein Sprung braucht verschiedene Von- und Bis-Werte.</translation>
    </message>
    <message>
        <source>The amplitude must be more than 0.</source>
        <translation>Die Amplitude muss größer als 0 sein.</translation>
    </message>
    <message>
        <source>A sweep needs a To frequency above its From frequency.</source>
        <translation>Ein Sweep braucht eine Bis-Frequenz über seiner Von-Frequenz.</translation>
    </message>
    <message>
        <source>This signal cannot be run: %1</source>
        <translation>Dieses Signal kann nicht gefahren werden: %1</translation>
    </message>
    <message>
        <source>%1 test of %2 s between %3 and %4; afterwards %5 is written back.</source>
        <translation>Test „%1“ über %2 s zwischen %3 und %4; danach wird %5 zurückgeschrieben.</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>Läuft …</translation>
    </message>
    <message>
        <source>Running: %1 of %2 s; sampled at %3 Hz.</source>
        <translation>Läuft: %1 von %2 s; abgetastet mit %3 Hz.</translation>
    </message>
    <message>
        <source>Running: %1 of %2 s; set value updated at %3 Hz, sampled at %4 Hz.</source>
        <translation>Läuft: %1 von %2 s; Sollwert mit %3 Hz aktualisiert, abgetastet mit %4 Hz.</translation>
    </message>
    <message>
        <source>The test ran to its end.</source>
        <translation>Der Test ist bis zum Ende gelaufen.</translation>
    </message>
    <message>
        <source>The test was stopped.</source>
        <translation>Der Test wurde gestoppt.</translation>
    </message>
    <message>
        <source>The travel window stopped the test: %1</source>
        <translation>Das Verfahrfenster hat den Test gestoppt: %1</translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation>Nichts wurde geschrieben: %1</translation>
    </message>
    <message>
        <source>The device stopped the test: %1</source>
        <translation>Das Gerät hat den Test gestoppt: %1</translation>
    </message>
    <message>
        <source>The link was lost: %1</source>
        <translation>Die Verbindung ist verloren: %1</translation>
    </message>
    <message>
        <source>%1 back to %2 (%3)</source>
        <translation>%1 zurück auf %2 (%3)</translation>
    </message>
    <message>
        <source>Restored: %1.</source>
        <translation>Zurückgesetzt: %1.</translation>
    </message>
    <message>
        <source>NOT restored: %1. Check the valve.</source>
        <translation>NICHT zurückgesetzt: %1. Prüfen Sie das Ventil.</translation>
    </message>
    <message>
        <source>For the test only: afterwards the values are written back.</source>
        <translation>Nur für den Test: danach werden die Werte zurückgeschrieben.</translation>
    </message>
    <message>
        <source>Workbench: run %1 done, values restored.</source>
        <translation>Werkbank: Lauf %1 fertig, Werte zurückgesetzt.</translation>
    </message>
    <message>
        <source>Workbench: run %1 ended, values NOT restored.</source>
        <translation>Werkbank: Lauf %1 beendet, Werte NICHT zurückgesetzt.</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Set value</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <source>Cycles/s</source>
        <translation>Zyklen/s</translation>
    </message>
    <message>
        <source>Set-value writes and reads per second; 0: as fast as the link allows (at most 1000).</source>
        <translation>Sollwert-Schreib- und Lesezyklen je Sekunde; 0: so schnell die Verbindung erlaubt (höchstens 1000).</translation>
    </message>
    <message>
        <source>as fast as possible</source>
        <translation>so schnell wie möglich</translation>
    </message>
    <message>
        <source>Travel window</source>
        <translation>Verfahrfenster</translation>
    </message>
    <message>
        <source>Stop the test when the actual value leaves the signal&apos;s range by more than this.</source>
        <translation>Den Test stoppen, wenn der Istwert den Bereich des Signals um mehr als diesen Wert verlässt.</translation>
    </message>
    <message>
        <source>Start Test</source>
        <translation>Test starten</translation>
    </message>
    <message>
        <source>Stop (Esc)</source>
        <translation>Stopp (Esc)</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Referenz</translation>
    </message>
</context>
<context>
    <name>vt::ui::WriteDialog</name>
    <message>
        <source>Write Changes</source>
        <translation>Änderungen schreiben</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>Neuer Wert</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <source>Every change is on the device.</source>
        <translation>Alle Änderungen sind im Gerät.</translation>
    </message>
    <message>
        <source>Not every change reached the device: see the result of each parameter.</source>
        <translation>Nicht alle Änderungen haben das Gerät erreicht: siehe Ergebnis je Parameter.</translation>
    </message>
    <message>
        <source>(unknown)</source>
        <translation>(unbekannt)</translation>
    </message>
    <message numerus="yes">
        <source>%n change(s) will be written to the device, one at a time, each read back.</source>
        <translation>
            <numerusform>%n Änderung wird in das Gerät geschrieben und zurückgelesen.</numerusform>
            <numerusform>%n Änderungen werden nacheinander in das Gerät geschrieben und jeweils zurückgelesen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>Schreibe…</translation>
    </message>
</context>
</TS>
