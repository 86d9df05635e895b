<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>QFileDialog</name>
    <message>
        <location filename="../../app/common/qt_standard_words.cpp" line="+47"/>
        <source>Look in:</source>
        <translation>Suchen in:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go forward</source>
        <translation>Vor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to the parent directory</source>
        <translation>Gehe zum übergeordneten Verzeichnis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Create a New Folder</source>
        <translation>Neuen Ordner erstellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change to list view mode</source>
        <translation>Wechsle zu Listenansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change to detail view mode</source>
        <translation>Wechsle zu Detailansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sidebar</source>
        <translation>Seitenleiste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>List of places and bookmarks</source>
        <translation>Liste der Orte und Lesezeichen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Files</source>
        <translation>Dateien</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recent Places</source>
        <translation>Zuletzt besucht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New Folder</source>
        <translation>&amp;Neues Verzeichnis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Choose</source>
        <translation>&amp;Auswählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation>Sind Sie sicher, dass Sie &apos;%1&apos; löschen möchten?</translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <location line="+1"/>
        <source>Computer</source>
        <translation>Computer</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <location line="-47"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save All</source>
        <translation>Alles speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Yes</source>
        <translation>&amp;Ja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yes to &amp;All</source>
        <translation>Ja, &amp;alle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;No</source>
        <translation>&amp;Nein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N&amp;o to All</source>
        <translation>N&amp;ein, keine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retry</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ignore</source>
        <translation>Ignorieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Help</source>
        <translation>Hilfe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore Defaults</source>
        <translation>Voreinstellungen</translation>
    </message>
</context>
<context>
    <name>QShortcut</name>
    <message>
        <location line="+4"/>
        <source>Space</source>
        <translation>Leertaste</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Backspace</source>
        <translation>Rücktaste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PgUp</source>
        <translation>Bild aufwärts</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PgDown</source>
        <translation>Bild abwärts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Up</source>
        <translation>Hoch</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Down</source>
        <translation>Herunter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ins</source>
        <translation>Einfg</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Del</source>
        <translation>Entf</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return</source>
        <translation>Return</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Print</source>
        <translation>Druck</translation>
    </message>
</context>
<context>
    <name>lb::BindingPanel</name>
    <message>
        <location filename="../../widgets/binding_panel.cpp" line="+24"/>
        <source>Vertex positions (location 0)</source>
        <translation>Vertex-Positionen (location 0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex normals (location 1)</source>
        <translation>Vertex-Normalen (location 1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture coordinates (location 2)</source>
        <translation>Texturkoordinaten (location 2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours (location 3)</source>
        <translation>Vertex-Farben (location 3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Nothing: the mesh has no array at location %1</source>
        <extracomment>%1 the location number a vertex input was linked at</extracomment>
        <translation>Nichts: das Mesh hat kein Array an location %1</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>A vertex input is fed by its location: layout(location = N), or the slot its name gives (aPos, a_normal, inTexCoord...).</source>
        <translation>Ein Vertex-Eingang wird über seine location gespeist: layout(location = N) oder der Platz, den sein Name sagt (aPos, a_normal, inTexCoord...).</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The built-in program draws: its inputs are the panels&apos;. A program of your own shows each input here with what feeds it, and you can choose what does.</source>
        <translation>Das eingebaute Programm zeichnet: seine Eingänge sind die der Panels. Ein eigenes Programm zeigt hier jeden Eingang mit dem, was ihn speist, und Sie können es wählen.</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n uniform(s) fed nothing: choose what feeds them; the choice is saved with the scene.</source>
        <extracomment>%n how many uniforms nothing feeds</extracomment>
        <translation>
            <numerusform>%n Uniform speist nichts: wählen Sie, was es speist; die Wahl wird mit der Szene gespeichert.</numerusform>
            <numerusform>%n Uniforms speist nichts: wählen Sie, was sie speist; die Wahl wird mit der Szene gespeichert.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What feeds each input of the program, chosen by its name; change a choice to feed another value. The choice is saved with the scene.</source>
        <translation>Was jeden Eingang des Programms speist, nach seinem Namen gewählt; ändern Sie eine Wahl, um einen anderen Wert zu speisen. Die Wahl wird mit der Szene gespeichert.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>By its name: %1</source>
        <extracomment>the entry that lets the uniform&apos;s name decide what feeds it; %1 what that is</extracomment>
        <translation>Nach seinem Namen: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>By its name: nothing (the name is no convention&apos;s)</source>
        <translation>Nach seinem Namen: nichts (der Name gehört zu keiner Konvention)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not fed: its own value (the Uniforms panel)</source>
        <translation>Nicht gespeist: sein eigener Wert (das Uniforms-Panel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not fed</source>
        <translation>Nicht gespeist</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Fed with: %1</source>
        <translation>Gespeist mit: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fed nothing: it stays 0 and decides the picture. Choose what the scene gives.</source>
        <translation>Nichts speist es: es bleibt 0 und bestimmt das Bild. Wählen Sie, was die Szene gibt.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fed nothing by the scene: its own value (the Uniforms panel&apos;s control, or its initialiser).</source>
        <translation>Die Szene speist es nicht: sein eigener Wert (das Steuerelement im Uniforms-Panel oder sein Initialisierer).</translation>
    </message>
</context>
<context>
    <name>lb::Bindings</name>
    <message>
        <location filename="../../render/glsl/bindings.cpp" line="+26"/>
        <source>Model-view matrix (camera from object)</source>
        <translation>Modelview-Matrix (Kamera aus Objekt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normal matrix (inverse transpose of model-view)</source>
        <translation>Normalenmatrix (inverse Transponierte der Modelview)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>View matrix (camera from world)</source>
        <translation>View-Matrix (Kamera aus Welt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>View&apos;s normal matrix (inverse transpose of view)</source>
        <translation>Normalenmatrix der View (inverse Transponierte der View)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection matrix</source>
        <translation>Projektionsmatrix</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position, in the Light panel&apos;s frame (x, y, z, w)</source>
        <translation>Lichtposition, in den Koordinaten des Licht-Panels (x, y, z, w)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position (camera coordinates)</source>
        <translation>Lichtposition (Kamerakoordinaten)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s ambient colour Ia</source>
        <translation>Ambiente Farbe des Lichts Ia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s diffuse colour Id</source>
        <translation>Diffuse Farbe des Lichts Id</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s specular colour Is</source>
        <translation>Spekulare Farbe des Lichts Is</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s ambient colour Ka</source>
        <translation>Ambiente Farbe des Materials Ka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s diffuse colour Kd</source>
        <translation>Diffuse Farbe des Materials Kd</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s specular colour Ks</source>
        <translation>Spekulare Farbe des Materials Ks</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shininess</source>
        <translation>Glanzexponent</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s frame (0 camera, 1 world, 2 object)</source>
        <translation>Koordinaten des Lichts (0 Kamera, 1 Welt, 2 Objekt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light on (1) or off (0)</source>
        <translation>Licht an (1) oder aus (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Specular model (0 Phong, 1 Blinn-Phong)</source>
        <translation>Spekulares Modell (0 Phong, 1 Blinn-Phong)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection (0 perspective, 1 parallel)</source>
        <translation>Projektion (0 perspektivisch, 1 parallel)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lighting on (1) or off (0)</source>
        <translation>Beleuchtung an (1) oder aus (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours on (1) or off (0)</source>
        <translation>Vertex-Farben an (1) oder aus (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture on (1) or off (0)</source>
        <translation>Textur an (1) oder aus (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The object&apos;s texture (unit 0)</source>
        <translation>Die Textur des Objekts (Einheit 0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation (kc, kl, kq)</source>
        <translation>Abschwächung (kc, kl, kq)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s axis, in the light&apos;s frame</source>
        <translation>Achse des Spots, in den Koordinaten des Lichts</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s cut-off angle (degrees)</source>
        <translation>Öffnungswinkel des Spots (Grad)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cosine of the spot&apos;s cut-off angle</source>
        <translation>Kosinus des Öffnungswinkels des Spots</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s exponent</source>
        <translation>Exponent des Spots</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ambient term on (1) or off (0)</source>
        <translation>Ambienter Term an (1) oder aus (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse term on (1) or off (0)</source>
        <translation>Diffuser Term an (1) oder aus (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Specular term on (1) or off (0)</source>
        <translation>Spekularer Term an (1) oder aus (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show choice (0 the colour, 1 N, 2 L...)</source>
        <translation>Anzeige-Wahl (0 die Farbe, 1 N, 2 L...)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Model matrix (world from object)</source>
        <translation>Modellmatrix (Welt aus Objekt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Model&apos;s normal matrix (inverse transpose of model)</source>
        <translation>Normalenmatrix des Modells (inverse Transponierte des Modells)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection times view</source>
        <translation>Projektion mal View</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection times model-view (MVP)</source>
        <translation>Projektion mal Modelview (MVP)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position (world coordinates)</source>
        <translation>Lichtposition (Weltkoordinaten)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Direction the light shines (world)</source>
        <translation>Richtung, in die das Licht scheint (Welt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Direction towards the light (world, unit)</source>
        <translation>Richtung zum Licht (Welt, Einheitsvektor)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Camera position (world coordinates)</source>
        <translation>Kameraposition (Weltkoordinaten)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ia times Ka</source>
        <translation>Ia mal Ka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Id times Kd</source>
        <translation>Id mal Kd</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Is times Ks</source>
        <translation>Is mal Ks</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s constant factor kc</source>
        <translation>Konstanter Faktor der Abschwächung kc</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s linear factor kl</source>
        <translation>Linearer Faktor der Abschwächung kl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s quadratic factor kq</source>
        <translation>Quadratischer Faktor der Abschwächung kq</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s axis (camera coordinates)</source>
        <translation>Achse des Spots (Kamerakoordinaten)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Half vector of a viewer far along +z (camera coordinates)</source>
        <translation>Halbvektor eines fernen Betrachters auf +z (Kamerakoordinaten)</translation>
    </message>
    <message>
        <location line="+126"/>
        <source>the binding %1=%2 is not used: %1 is not of the type that %2 gives (a matrix, numbers, a texture)</source>
        <extracomment>%1 the uniform&apos;s name, %2 the key chosen for it (model-view, light-diffuse)</extracomment>
        <translation>die Bindung %1=%2 wird nicht verwendet: %1 hat nicht den Typ, den %2 gibt (eine Matrix, Zahlen, eine Textur)</translation>
    </message>
</context>
<context>
    <name>lb::BoundedRead</name>
    <message>
        <location filename="../../render/model/io/bounded_read.cpp" line="+35"/>
        <location line="+6"/>
        <source>no such file</source>
        <translation>Datei nicht vorhanden</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>a loop of symbolic links</source>
        <translation>eine Schleife symbolischer Links</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a symbolic link to %1, which does not exist</source>
        <translation>ein symbolischer Link auf das nicht vorhandene Ziel %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 MB</source>
        <translation>%1 MB</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 KiB</source>
        <translation>%1 KiB</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1, %2</source>
        <extracomment>a file&apos;s size limit (%1, &quot;64 MB&quot;) and where it comes from (%2, &quot;the import memory limit&quot;)</extracomment>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: not a regular file (a folder, a device or a pipe)</source>
        <translation>%1: keine reguläre Datei (ein Ordner, ein Gerät oder eine Pipe)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 is more than %3 may be (%4)</source>
        <extracomment>%1 a path, %2 its size, %3 a kind of file (&quot;a scene file&quot;), %4 the limit (&quot;64 MB&quot;)</extracomment>
        <translation>%1: %2 sind mehr, als %3 haben darf (%4)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: more than %2 may be (%3)</source>
        <extracomment>%1 a path, %2 a kind of file (&quot;a scene file&quot;), %3 the limit (&quot;64 MB&quot;)</extracomment>
        <translation>%1: mehr, als %2 haben darf (%3)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: not saved: %2 would take %3, more than %4 may be (%5), so it could not be opened again</source>
        <extracomment>%1 a path, %2 what is saved (&quot;the scene&quot;), %3 its size, %4 a kind of file (&quot;a scene file&quot;), %5 the limit (&quot;64 MB&quot;)</extracomment>
        <translation>%1: nicht gespeichert: %2 würde %3 belegen, mehr als %4 haben darf (%5), und ließe sich dann nicht wieder öffnen</translation>
    </message>
</context>
<context>
    <name>lb::CaptionDialog</name>
    <message>
        <location filename="../../widgets/caption_dialog.cpp" line="+21"/>
        <source>English</source>
        <translation>Englisch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Portuguese</source>
        <translation>Portugiesisch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>German</source>
        <translation>Deutsch</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+43"/>
        <source>Edit Caption</source>
        <translation>Beschriftung bearbeiten</translation>
    </message>
    <message>
        <location line="-41"/>
        <source>What the class reads under the view. Markdown: *italic*, **bold**, `code`, lists. An empty language shows English.</source>
        <translation>Was die Klasse unter der Ansicht liest. Markdown: *kursiv*, **fett**, `Code`, Listen. Eine leere Sprache zeigt Englisch.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (%2)</source>
        <extracomment>a caption&apos;s tab: %1 the language&apos;s name, %2 its code (en, pt, de)</extracomment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>The %1 caption has %2 characters; a caption holds at most %3. Nothing was changed yet: shorten it, or Cancel.</source>
        <extracomment>%1 the language&apos;s code (en, pt, de); %2, %3 counts</extracomment>
        <translation>Die Beschriftung (%1) hat %2 Zeichen; eine Beschriftung fasst höchstens %3. Noch wurde nichts geändert: Kürzen Sie sie oder brechen Sie ab.</translation>
    </message>
</context>
<context>
    <name>lb::ChoiceLabels</name>
    <message>
        <location filename="../../widgets/choice_labels.cpp" line="+14"/>
        <source>camera</source>
        <comment>light frame</comment>
        <translation>Kamerakoordinaten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>world</source>
        <comment>light frame</comment>
        <translation>Weltkoordinaten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>object</source>
        <comment>light frame</comment>
        <translation>Objektkoordinaten</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>gouraud</source>
        <comment>shading</comment>
        <extracomment>Gouraud shading (per vertex), as in &quot;gouraud shading&quot;</extracomment>
        <translation>Gouraud</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>phong</source>
        <comment>shading</comment>
        <extracomment>Phong shading (per fragment), as in &quot;phong shading&quot;</extracomment>
        <translation>Phong</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>flat</source>
        <comment>shading</comment>
        <extracomment>flat shading (per triangle), as in &quot;flat shading&quot;</extracomment>
        <translation>flach</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>colour</source>
        <comment>show</comment>
        <translation>Farbe</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>normal</source>
        <comment>show</comment>
        <extracomment>the normal N, drawn as a colour</extracomment>
        <translation>Normale N</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>light</source>
        <comment>show</comment>
        <extracomment>the light vector L, drawn as a colour</extracomment>
        <translation>Lichtvektor L</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>view</source>
        <comment>show</comment>
        <extracomment>the view vector V, drawn as a colour</extracomment>
        <translation>Blickvektor V</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>half</source>
        <comment>show</comment>
        <extracomment>the half vector H, drawn as a colour</extracomment>
        <translation>Halbvektor H</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>reflect</source>
        <comment>show</comment>
        <extracomment>the reflected light R, drawn as a colour</extracomment>
        <translation>Reflexionsvektor R</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ndotl</source>
        <comment>show</comment>
        <extracomment>N·L drawn as grey</extracomment>
        <translation>N·L</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>specular</source>
        <comment>show</comment>
        <extracomment>the specular factor drawn as grey</extracomment>
        <translation>Glanzfaktor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>attenuation</source>
        <comment>show</comment>
        <extracomment>the attenuation drawn as grey</extracomment>
        <translation>Abschwächung</translation>
    </message>
    <message>
        <location filename="../../render/model/lighting/lighting_models.cpp" line="+29"/>
        <source>phong</source>
        <comment>specular</comment>
        <extracomment>Phong&apos;s specular term (R.V)^n, as in &quot;phong specular&quot;</extracomment>
        <translation>Phong</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>blinn</source>
        <comment>specular</comment>
        <extracomment>Blinn-Phong&apos;s specular term (N.H)^n, as in &quot;blinn specular&quot;</extracomment>
        <translation>Blinn-Phong</translation>
    </message>
</context>
<context>
    <name>lb::ColorEdit</name>
    <message>
        <location filename="../../widgets/color_edit.cpp" line="+21"/>
        <source>Pick %1 with the colour dialog</source>
        <translation>%1 mit dem Farbdialog wählen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1, %2 channel (0 to 1)</source>
        <translation>%1, Kanal %2 (0 bis 1)</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Choose %1</source>
        <translation>%1 wählen</translation>
    </message>
</context>
<context>
    <name>lb::DifferenceScaleLabels</name>
    <message>
        <location filename="../../widgets/difference_scale_labels.cpp" line="+55"/>
        <source>%1+</source>
        <extracomment>the top of the difference scale: this difference (of 255) and more</extracomment>
        <translation>%1+</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>|A-B| of 255</source>
        <extracomment>the difference scale&apos;s title: |A-B| the difference of sides A and B, out of 255</extracomment>
        <translation>|A-B| von 255</translation>
    </message>
</context>
<context>
    <name>lb::EditorPanel</name>
    <message>
        <location filename="../../widgets/editor_panel.cpp" line="+41"/>
        <source>vertex</source>
        <extracomment>the shader stage a message is about, before its line:column</extracomment>
        <translation>Vertex</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>fragment</source>
        <extracomment>the shader stage a message is about, before its line:column</extracomment>
        <translation>Fragment</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>link</source>
        <extracomment>a message of the linker, about no single stage</extracomment>
        <translation>Linker</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the scene&apos;s shaders</source>
        <translation>die Shader der Szene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>your shaders</source>
        <translation>Ihre Shader</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (edited)</source>
        <translation>%1 (bearbeitet)</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+137"/>
        <source>Presets</source>
        <translation>Vorlagen</translation>
    </message>
    <message>
        <location line="-129"/>
        <source>Presets: the built-in programs, the slides&apos; shaders as printed, toon</source>
        <translation>Vorlagen: die eingebauten Programme, die Shader der Folien wie abgedruckt, Toon</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Compile</source>
        <translation>Kompilieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compile and link now (Ctrl+Enter)</source>
        <translation>Jetzt kompilieren und linken (Strg+Eingabe)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Live</source>
        <extracomment>recompile while typing (a switch)</extracomment>
        <translation>Live</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recompile after a pause in typing; off: only on Ctrl+Enter</source>
        <translation>Nach einer Tipppause neu kompilieren; aus: nur mit Strg+Eingabe</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> ms</source>
        <extracomment>milliseconds, after the number</extracomment>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The pause after the last key before a live recompile (wheel or arrow keys change it)</source>
        <translation>Die Pause nach der letzten Taste vor einem Live-Neukompilieren (Mausrad oder Pfeiltasten ändern sie)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Find (Ctrl+F)</source>
        <translation>Suchen (Strg+F)</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+148"/>
        <source>Vertex</source>
        <translation>Vertex</translation>
    </message>
    <message>
        <location line="-147"/>
        <location line="+150"/>
        <source>Fragment</source>
        <translation>Fragment</translation>
    </message>
    <message>
        <location line="-144"/>
        <source>Click a message to go to its line</source>
        <translation>Klicken Sie auf eine Meldung, um zu ihrer Zeile zu springen</translation>
    </message>
    <message>
        <location line="+125"/>
        <source>%1 is gone from the disk; your text is kept</source>
        <translation>%1 ist nicht mehr auf der Festplatte; Ihr Text bleibt erhalten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 changed on disk; your unsaved edits are kept (Open it again to take the disk&apos;s version)</source>
        <translation>%1 wurde auf der Festplatte geändert; Ihre ungespeicherten Änderungen bleiben erhalten (erneut öffnen, um die Version auf der Festplatte zu laden)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Vertex - %1</source>
        <extracomment>the vertex shader&apos;s tab; %1 its file&apos;s name</extracomment>
        <translation>Vertex - %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fragment - %1</source>
        <extracomment>the fragment shader&apos;s tab; %1 its file&apos;s name</extracomment>
        <translation>Fragment - %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Your unsaved shader edits from the last session are back</source>
        <translation>Ihre ungespeicherten Shader-Änderungen aus der letzten Sitzung sind wieder da</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>%1  error: %2</source>
        <extracomment>%1 where (fragment 5:3); %2 the compiler&apos;s message</extracomment>
        <translation>%1  Fehler: %2</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1  warning: %2</source>
        <translation>%1  Warnung: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>linked, %n warning(s)</source>
        <translation>
            <numerusform>gelinkt, %n Warnung</numerusform>
            <numerusform>gelinkt, %n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linked</source>
        <translation>gelinkt</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n error(s): last good program drawing</source>
        <translation>
            <numerusform>%n Fehler: das letzte funktionierende Programm zeichnet</numerusform>
            <numerusform>%n Fehler: das letzte funktionierende Programm zeichnet</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lb::Exercise</name>
    <message>
        <location filename="../../render/model/scene/exercise.cpp" line="+84"/>
        <source>not a number of points from 0 to %1, nor a list of one per case</source>
        <extracomment>%1 the largest number of points (&quot;1000000&quot;)</extracomment>
        <translation>weder eine Punktzahl von 0 bis %1 noch eine Liste mit einer pro Fall</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>each case&apos;s points must be a number from 0 to %1</source>
        <translation>die Punkte jedes Falls müssen eine Zahl von 0 bis %1 sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 values for %2 cases (one per case)</source>
        <extracomment>%1 how many points the list gives, %2 how many cases the exercise has</extracomment>
        <translation>%1 Werte für %2 Fälle (einer pro Fall)</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>%1 (%2)</source>
        <extracomment>a field of an exercise as the file spells it (%1, &quot;exercise.grading.cases&quot;) and why it was not used (%2)</extracomment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: not an object</source>
        <translation>%1: kein JSON-Objekt</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+38"/>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="+55"/>
        <location line="+11"/>
        <location line="+20"/>
        <source>unknown field</source>
        <translation>unbekanntes Feld</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>%1: needs both a vertex and a fragment shader</source>
        <translation>%1: braucht sowohl einen Vertex- als auch einen Fragment-Shader</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+5"/>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="-51"/>
        <source>not %1</source>
        <extracomment>%1 the words a file may give, as it spells them (&quot;phong, gouraud, flat&quot;)</extracomment>
        <translation>keiner der Werte %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: no reference program (&quot;reference&quot;: {&quot;vertex&quot;: ..., &quot;fragment&quot;: ...} or {&quot;builtIn&quot;: {...}})</source>
        <translation>%1: kein Referenzprogramm (&quot;reference&quot;: {&quot;vertex&quot;: ..., &quot;fragment&quot;: ...} oder {&quot;builtIn&quot;: {...}})</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a number</source>
        <translation>keine Zahl</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of range, clamped</source>
        <translation>außerhalb des zulässigen Bereichs, auf die Grenze gesetzt</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>not [width, height] in whole pixels, 16 to %1</source>
        <translation>nicht [Breite, Höhe] in ganzen Pixeln, 16 bis %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not a list of parameters; all of them vary</source>
        <translation>keine Liste von Parametern; alle werden variiert</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no such parameter &apos;%1&apos;; those are %2</source>
        <translation>unbekannter Parameter &apos;%1&apos;; möglich sind %2</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="+11"/>
        <source>not true or false</source>
        <translation>weder true noch false</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+17"/>
        <source>not an object</source>
        <translation>kein Objekt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>not a name of 1 to %1 characters; the mistake is left out</source>
        <translation>kein Name mit 1 bis %1 Zeichen; der Fehler wird weggelassen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>no usable hint; the mistake is left out</source>
        <translation>kein verwendbarer Hinweis; der Fehler wird weggelassen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>not a shader&apos;s text of up to 1 MiB; the mistake is left out</source>
        <translation>kein Shader-Text von bis zu 1 MiB; der Fehler wird weggelassen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>both a program and a built-in; the mistake is left out</source>
        <translation>sowohl ein Programm als auch ein eingebautes; der Fehler wird weggelassen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needs both a vertex and a fragment shader: the reference is the built-in program; the mistake is left out</source>
        <translation>braucht einen Vertex- und einen Fragment-Shader: Die Referenz ist das eingebaute Programm; der Fehler wird weggelassen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>neither a program (&quot;vertex&quot;, &quot;fragment&quot;) nor &quot;builtIn&quot;: {...}; the mistake is left out</source>
        <translation>weder ein Programm (&quot;vertex&quot;, &quot;fragment&quot;) noch &quot;builtIn&quot;: {...}; der Fehler wird weggelassen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a built-in mistake needs a built-in reference; give the mistake as a program; the mistake is left out</source>
        <translation>ein eingebauter Fehler braucht eine eingebaute Referenz; geben Sie den Fehler als Programm an; der Fehler wird weggelassen</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a list</source>
        <translation>keine Liste</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>more than %1 mistakes; the rest are left out</source>
        <translation>mehr als %1 Fehler; die übrigen werden weggelassen</translation>
    </message>
</context>
<context>
    <name>lb::ExercisePanel</name>
    <message>
        <location filename="../../widgets/exercise_panel.cpp" line="+35"/>
        <source>light position</source>
        <translation>Lichtposition</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>point or directional</source>
        <translation>Punktlicht oder gerichtetes Licht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>light frame</source>
        <translation>Koordinatensystem des Lichts</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>light colours</source>
        <translation>Lichtfarben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>material</source>
        <translation>Material</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>projection</source>
        <translation>Projektion</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>non-uniform scale</source>
        <translation>ungleichmäßige Skalierung</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>nothing (every case is the scene as it is)</source>
        <translation>nichts (jeder Fall ist die Szene, wie sie ist)</translation>
    </message>
    <message>
        <location line="+30"/>
        <location line="+141"/>
        <source>Check my work</source>
        <translation>Arbeit prüfen</translation>
    </message>
    <message>
        <location line="-140"/>
        <source>Draws the exercise&apos;s cases with the program in the editor and with the reference, as the teacher&apos;s grading does, and lists each case (F9)</source>
        <translation>Zeichnet die Fälle der Übung mit dem Programm im Editor und mit der Referenz, wie es die Bewertung der Lehrkraft tut, und listet jeden Fall auf (F9)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Out of date: the program in the editor has changed since this check. Check my work (F9) checks it as it is now.</source>
        <translation>Veraltet: Das Programm im Editor wurde seit dieser Prüfung geändert. „Arbeit prüfen“ (F9) prüft es im jetzigen Zustand.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Case</source>
        <translation>Fall</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Largest</source>
        <translation>Größte Diff.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Within</source>
        <translation>In Toleranz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The largest difference of a channel, out of 255</source>
        <translation>Die größte Differenz eines Kanals, von 255</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Click a case to see it in the difference view</source>
        <translation>Klicken Sie auf einen Fall, um ihn in der Differenzansicht zu sehen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Back to my scene</source>
        <translation>Zurück zu meiner Szene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The scene as it was before a case was shown</source>
        <translation>Die Szene, wie sie war, bevor ein Fall gezeigt wurde</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>No exercise is open</source>
        <translation>Keine Übung geöffnet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An exercise is a scene file with a task, the teacher&apos;s reference program and how it is graded. File &gt; Examples &gt; &quot;Exercise: per-fragment lighting&quot; is one; File &gt; Open Scene opens others.</source>
        <translation>Eine Übung ist eine Szenendatei mit einer Aufgabe, dem Referenzprogramm der Lehrkraft und der Art der Bewertung. Datei &gt; Beispiele &gt; „Übung: Beleuchtung pro Fragment“ ist eine davon; Datei &gt; Szene öffnen öffnet weitere.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The share of the pixels either program draws that are within %1/255 of the reference, at %2 x %3: the difference view counts a case alike (at its own size)</source>
        <translation>Der Anteil der von einem der beiden Programme gezeichneten Pixel, die höchstens %1/255 von der Referenz abweichen, bei %2 x %3: Die Differenzansicht zählt einen Fall genauso (in ihrer eigenen Größe)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This exercise cannot be checked: its reference is missing or unusable.</source>
        <translation>Diese Übung kann nicht geprüft werden: Ihre Referenz fehlt oder ist unbrauchbar.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference: the built-in program, %1 shading, %2 specular.</source>
        <extracomment>%1 the shading (gouraud, phong, flat); %2 the specular term (phong, blinn)</extracomment>
        <translation>Referenz: das eingebaute Programm, Schattierung %1, spiegelnder Anteil %2.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reference: the teacher&apos;s program (not shown; it is side B of the compare views, key C).</source>
        <translation>Referenz: das Programm der Lehrkraft (nicht angezeigt; es ist Seite B der Vergleichsansichten, Taste C).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 cases at %2 x %3 pixels; a case passes when %4 of its pixels are within %5/255. The cases vary: %6.</source>
        <translation>%1 Fälle bei %2 x %3 Pixeln; ein Fall ist bestanden, wenn %4 seiner Pixel höchstens %5/255 abweichen. Die Fälle variieren: %6.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>One frame of your program may take at most %1; a program that would take longer is refused.</source>
        <translation>Ein Bild Ihres Programms darf höchstens %1 dauern; ein Programm, das länger bräuchte, wird abgelehnt.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cancel the check</source>
        <translation>Prüfung abbrechen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Checking: the cases are drawn with your program and the reference...</source>
        <translation>Prüfung läuft: Die Fälle werden mit Ihrem Programm und der Referenz gezeichnet...</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Your program does not compile:
%1</source>
        <extracomment>%1 the compiler&apos;s messages</extracomment>
        <translation>Ihr Programm lässt sich nicht kompilieren:
%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Your program does not compile</source>
        <translation>Ihr Programm lässt sich nicht kompilieren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Your program does not link:
%1</source>
        <extracomment>%1 the linker&apos;s messages</extracomment>
        <translation>Ihr Programm lässt sich nicht linken:
%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Your program does not link</source>
        <translation>Ihr Programm lässt sich nicht linken</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Your program was refused:
%1</source>
        <extracomment>%1 why it was refused (a loop that never ends, a frame too slow)</extracomment>
        <translation>Ihr Programm wurde abgelehnt:
%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Your program was refused</source>
        <translation>Ihr Programm wurde abgelehnt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This exercise cannot check your work: one of the known mistakes it lists cannot be drawn. Tell your teacher:
%1</source>
        <extracomment>%1 which of the exercise&apos;s known mistakes, and why (the driver&apos;s words)</extracomment>
        <translation>Diese Übung kann Ihre Arbeit nicht prüfen: Einer der bekannten Fehler, die sie aufführt, lässt sich nicht zeichnen. Sagen Sie es Ihrer Lehrkraft:
%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The check could not start:
%1</source>
        <extracomment>%1 why the checking process did not start</extracomment>
        <translation>Die Prüfung konnte nicht starten:
%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The check could not start</source>
        <translation>Die Prüfung konnte nicht starten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not checked: %1:
%2</source>
        <extracomment>%1 the grading&apos;s status word (English, as the report has it); %2 its reason</extracomment>
        <translation>Nicht geprüft: %1:
%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: %1</source>
        <translation>Nicht geprüft: %1</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>Your failing cases match the exercise&apos;s known mistake &quot;%1&quot; in %2 of their pixels, far more than they match the reference</source>
        <extracomment>%1 the mistake&apos;s name as the exercise gives it (data, English); %2 a share (&quot;98.5%&quot;)</extracomment>
        <translation>Ihre fehlgeschlagenen Fälle stimmen in %2 ihrer Pixel mit dem bekannten Fehler „%1“ der Übung überein, weit mehr als mit der Referenz</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Check My Work, at %1 x %2: largest %3/255, %4 within %5/255</source>
        <extracomment>the difference view&apos;s caption for a case of the list; %1 x %2 the check&apos;s frame</extracomment>
        <translation>Arbeit prüfen, bei %1 x %2: größte %3/255, %4 innerhalb %5/255</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Check My Work, at %1 x %2: nothing drawn</source>
        <translation>Arbeit prüfen, bei %1 x %2: nichts gezeichnet</translation>
    </message>
    <message>
        <location line="-93"/>
        <source>The check took too long (%1) and was stopped</source>
        <extracomment>%1 how long it was given</extracomment>
        <translation>Die Prüfung dauerte zu lange (%1) und wurde abgebrochen</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Passed: all %1 cases (in each, at least %2 of the pixels within %3/255); largest difference %4/255</source>
        <translation>Bestanden: alle %1 Fälle (in jedem mindestens %2 der Pixel innerhalb von %3/255); größte Differenz %4/255</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Not yet: %1 of %2 cases pass; largest difference %3/255</source>
        <translation>Noch nicht: %1 von %2 Fällen bestanden; größte Differenz %3/255</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Click a case to see it in the difference view.</source>
        <translation>Klicken Sie auf einen Fall, um ihn in der Differenzansicht zu sehen.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (as given)</source>
        <extracomment>case 0 of the list: the exercise&apos;s scene as it is, not varied</extracomment>
        <translation>%1 (wie vorgegeben)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>passed</source>
        <translation>bestanden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>failed</source>
        <translation>nicht bestanden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nothing drawn</source>
        <translation>nichts gezeichnet</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Largest difference at (%1, %2) of the %3 x %4 frame; %5 pixels drawn</source>
        <translation>Größte Differenz bei (%1, %2) im Bild von %3 x %4; %5 Pixel gezeichnet</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 pixels drawn</source>
        <translation>%1 Pixel gezeichnet</translation>
    </message>
</context>
<context>
    <name>lb::ExportSizeDialog</name>
    <message>
        <location filename="../../widgets/export_size_dialog.cpp" line="+12"/>
        <source>Export Image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> px</source>
        <extracomment>pixels, after the number</extracomment>
        <translation> px</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The view is drawn again at this size, not scaled.</source>
        <translation>Die Ansicht wird in dieser Größe neu gezeichnet, nicht skaliert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose File...</source>
        <translation>Datei wählen...</translation>
    </message>
</context>
<context>
    <name>lb::FileArguments</name>
    <message>
        <location filename="../../app/window/file_arguments.cpp" line="+52"/>
        <source>Files not opened</source>
        <translation>Nicht geöffnete Dateien</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lightbench opens one scene or lesson at a time, the first file given (%1); the files below were not opened. Open them with File &gt; Open Scene or File &gt; Open Lesson.</source>
        <translation>lightbench öffnet jeweils nur eine Szene oder Lektion: die erste angegebene Datei (%1). Die Dateien unten wurden nicht geöffnet. Öffnen Sie sie mit Datei &gt; Szene öffnen oder Datei &gt; Lektion öffnen.</translation>
    </message>
</context>
<context>
    <name>lb::FileLimit</name>
    <message>
        <location filename="../../render/import/import_process.cpp" line="+55"/>
        <source>a texture file</source>
        <translation>eine Texturdatei</translation>
    </message>
    <message>
        <location line="+129"/>
        <source>a mesh file</source>
        <translation>eine Mesh-Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the import memory limit</source>
        <translation>die Speichergrenze für den Import</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/lesson.cpp" line="+208"/>
        <location line="+42"/>
        <source>a lesson file</source>
        <translation>eine Lektionsdatei</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>the lesson</source>
        <translation>die Lektion</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/scene_file.cpp" line="+186"/>
        <location line="+15"/>
        <source>a scene file</source>
        <translation>eine Szenendatei</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>the scene</source>
        <translation>die Szene</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/shader_document.cpp" line="+21"/>
        <source>a shader</source>
        <translation>ein Shader</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/texture_file.cpp" line="+31"/>
        <source>an image</source>
        <translation>ein Bild</translation>
    </message>
    <message>
        <location filename="../../app/window/settings_store.cpp" line="+32"/>
        <location line="+20"/>
        <source>a settings file</source>
        <translation>eine Einstellungsdatei</translation>
    </message>
</context>
<context>
    <name>lb::FrameLook</name>
    <message>
        <location filename="../../render/model/measure/frame_look.cpp" line="+50"/>
        <source>your program draws nothing: every pixel of the frame is the background (the object is outside the view, or a matrix fed nothing collapses it; the Bindings tab shows what feeds each input)</source>
        <translation>Ihr Programm zeichnet nichts: jedes Pixel des Bildes ist der Hintergrund (das Objekt liegt außerhalb der Ansicht, oder eine Matrix, die nichts speist, lässt es zusammenfallen; der Tab Bindungen zeigt, was jeden Eingang speist)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>your program draws the object all black: if it is not meant to be, a light or colour input it reads may be fed nothing (the Bindings tab shows what feeds each input)</source>
        <translation>Ihr Programm zeichnet das Objekt ganz schwarz: wenn es nicht so sein soll, speist vielleicht nichts einen Licht- oder Farbeingang, den es liest (der Tab Bindungen zeigt, was jeden Eingang speist)</translation>
    </message>
</context>
<context>
    <name>lb::Grading</name>
    <message>
        <location filename="../../render/model/grading/grading.cpp" line="+136"/>
        <source>passed</source>
        <extracomment>the outcome of a case, at the end of a grading sheet&apos;s title</extracomment>
        <translation>bestanden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>failed</source>
        <translation>nicht bestanden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 - case %2: largest difference %3/255, %4% of %5 pixels within tolerance, %6</source>
        <translation>%1 - Fall %2: größte Differenz %3/255, %4% von %5 Pixeln innerhalb der Toleranz, %6</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 - case %2: largest difference %3/255 at (%4, %5), %6% of %7 pixels within tolerance, %8</source>
        <extracomment>%4, %5: the pixel that differs most</extracomment>
        <translation>%1 - Fall %2: größte Differenz %3/255 bei (%4, %5), %6% von %7 Pixeln innerhalb der Toleranz, %8</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>student</source>
        <extracomment>the captions under a grading sheet&apos;s three frames</extracomment>
        <translation>Abgabe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>|student - reference| (white: 64/255)</source>
        <translation>|Abgabe - Referenz| (weiß: 64/255)</translation>
    </message>
</context>
<context>
    <name>lb::Help</name>
    <message>
        <location filename="../../app/window/help.cpp" line="+52"/>
        <source>%1, %2</source>
        <extracomment>shortcuts that do the same: all but the last two, &quot;Ctrl++, Ctrl+= or ...&quot;</extracomment>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 or %2</source>
        <extracomment>shortcuts that do the same: &quot;F11 or F5&quot;</extracomment>
        <translation>%1 oder %2</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Menus</source>
        <extracomment>Help &gt; Keyboard Shortcuts: the heading over every menu&apos;s keys</extracomment>
        <translation>Menüs</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Shader editor</source>
        <translation>Shader-Editor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>compile and link now</source>
        <translation>jetzt kompilieren und linken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>find in the shader</source>
        <translation>im Shader suchen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>undo / redo (also what a preset, an example or a reset replaced)</source>
        <translation>rückgängig / wiederherstellen (auch was eine Vorlage, ein Beispiel oder ein Zurücksetzen ersetzt hat)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>complete the word</source>
        <translation>Wort vervollständigen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>delete / duplicate the line</source>
        <translation>Zeile löschen / duplizieren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>View</source>
        <extracomment>Help &gt; Keyboard Shortcuts: the heading over the mouse and keys of the 3D view (not the View menu)</extracomment>
        <translation>Ansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>left drag</source>
        <translation>mit der linken Maustaste ziehen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>orbit the camera</source>
        <translation>Kamera um die Szene kreisen lassen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>click</source>
        <translation>Klick</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>select the object under the cursor</source>
        <translation>Objekt unter dem Mauszeiger auswählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>right or middle drag</source>
        <translation>mit der rechten oder mittleren Maustaste ziehen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>pan</source>
        <translation>verschieben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel</source>
        <translation>Mausrad</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>zoom</source>
        <translation>zoomen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+click, Shift+click</source>
        <extracomment>the keys as the keyboard names them (Ctrl, Shift), held while clicking</extracomment>
        <translation>Strg+Klick, Umschalt+Klick</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>probe the surface point (drag to move it)</source>
        <translation>Oberflächenpunkt mit der Sonde messen (ziehen verschiebt ihn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drag the wipe&apos;s line</source>
        <translation>die Linie der Wischblende ziehen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>move the wipe (compare)</source>
        <translation>Wischblende verschieben (Vergleich)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>drop a file</source>
        <translation>Datei ablegen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>open a mesh, a scene, a lesson or a shader pair</source>
        <translation>ein Mesh, eine Szene, eine Lektion oder ein Shader-Paar öffnen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Keyboard shortcuts - lightbench</source>
        <translation>Tastenkürzel - lightbench</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Features - lightbench</source>
        <translation>Funktionen - lightbench</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The README is missing from this build.</source>
        <translation>Die README fehlt in diesem Build.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>About lightbench</source>
        <translation>Über lightbench</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;lightbench %1&lt;/h3&gt;&lt;p&gt;A workbench for the lighting model of computer graphics courses: ambient, diffuse and specular terms, Phong and Blinn-Phong, Gouraud and Phong shading, every pixel checked against a CPU reference.&lt;/p&gt;&lt;p&gt;Qt %2 (built with %3)&lt;br&gt;%4&lt;/p&gt;</source>
        <translation>&lt;h3&gt;lightbench %1&lt;/h3&gt;&lt;p&gt;Eine Werkbank für das Beleuchtungsmodell aus Vorlesungen zur Computergrafik: ambienter, diffuser und spiegelnder Anteil, Phong und Blinn-Phong, Gouraud- und Phong-Schattierung, jedes Pixel geprüft gegen eine CPU-Referenz.&lt;/p&gt;&lt;p&gt;Qt %2 (erstellt mit %3)&lt;br&gt;%4&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>OpenGL not started yet</source>
        <translation>OpenGL noch nicht gestartet</translation>
    </message>
</context>
<context>
    <name>lb::ImageTruncation</name>
    <message>
        <location filename="../../render/model/io/image_truncation.cpp" line="+33"/>
        <source>no image data (no scan)</source>
        <translation>keine Bilddaten (kein Scan-Abschnitt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file ends inside the image data (no end-of-image marker): cut short?</source>
        <translation>die Datei endet mitten in den Bilddaten (keine End-of-Image-Markierung): abgeschnitten?</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the file ends inside its header</source>
        <translation>die Datei endet mitten im Dateikopf</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the file ends inside the image data (%1 of %2 bytes): cut short?</source>
        <translation>die Datei endet mitten in den Bilddaten (%1 von %2 Bytes): abgeschnitten?</translation>
    </message>
</context>
<context>
    <name>lb::ImportProcess</name>
    <message>
        <location filename="../../render/import/import_process.cpp" line="-156"/>
        <source>the importer crashed with a segmentation fault while reading this file; the workbench is fine</source>
        <translation>der Import-Helfer ist beim Lesen dieser Datei mit einem Speicherzugriffsfehler (Segmentation Fault) abgestürzt; die Werkbank arbeitet normal weiter</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the importer crashed with an abort while reading this file; the workbench is fine</source>
        <translation>der Import-Helfer ist beim Lesen dieser Datei mit einem Abbruch (Abort) abgestürzt; die Werkbank arbeitet normal weiter</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with a bus error while reading this file; the workbench is fine</source>
        <translation>der Import-Helfer ist beim Lesen dieser Datei mit einem Busfehler abgestürzt; die Werkbank arbeitet normal weiter</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with an arithmetic error while reading this file; the workbench is fine</source>
        <translation>der Import-Helfer ist beim Lesen dieser Datei mit einem arithmetischen Fehler abgestürzt; die Werkbank arbeitet normal weiter</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the importer crashed with an illegal instruction while reading this file; the workbench is fine</source>
        <translation>der Import-Helfer ist beim Lesen dieser Datei mit einem ungültigen Maschinenbefehl abgestürzt; die Werkbank arbeitet normal weiter</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with signal %1 (%2) while reading this file; the workbench is fine</source>
        <extracomment>%1 a signal&apos;s number, %2 the system&apos;s name for it</extracomment>
        <translation>der Import-Helfer ist beim Lesen dieser Datei mit Signal %1 (%2) abgestürzt; die Werkbank arbeitet normal weiter</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>texture &apos;%1&apos;: outside the mesh&apos;s folder</source>
        <translation>Textur &apos;%1&apos;: außerhalb des Ordners des Meshes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>texture &apos;%1&apos; not found</source>
        <translation>Textur &apos;%1&apos; nicht gefunden</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1: cannot start the import helper &apos;%2&apos;: %3</source>
        <translation>%1: Der Import-Helfer &apos;%2&apos; kann nicht gestartet werden: %3</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1: not readable (permissions)</source>
        <translation>%1: nicht lesbar (Zugriffsrechte)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the file is empty</source>
        <translation>%1: Die Datei ist leer</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1: cancelled</source>
        <translation>%1: abgebrochen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: gave up after %2 s (the import time limit)</source>
        <translation>%1: nach %2 s aufgegeben (die Zeitgrenze für den Import)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>gave up after %1 s of CPU time (the import time limit)</source>
        <translation>nach %1 s CPU-Zeit aufgegeben (die Zeitgrenze für den Import)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import helper was killed (by the system, for memory?)</source>
        <translation>der Import-Helfer wurde beendet (vom System, wegen Speichermangel?)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of memory: reading this file needs more than the import memory limit (%1 MB)</source>
        <translation>nicht genug Speicher: Das Lesen dieser Datei braucht mehr als die Speichergrenze für den Import (%1 MB)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the import helper stopped (exit code %1) before sending the whole mesh</source>
        <translation>der Import-Helfer hat sich beendet (Exit-Code %1), bevor er das ganze Mesh gesendet hatte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import helper stopped (exit code %1) before sending the whole mesh: %2</source>
        <extracomment>%2 the last line the helper wrote on its error output (its own words, in English)</extracomment>
        <translation>der Import-Helfer hat sich beendet (Exit-Code %1), bevor er das ganze Mesh gesendet hatte: %2</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>embedded texture unreadable: %1</source>
        <translation>eingebettete Textur nicht lesbar: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>texture %1</source>
        <extracomment>%1 why a texture file cannot be used, &quot;PATH: reason&quot;</extracomment>
        <translation>Textur %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>texture &apos;%1&apos;: %2</source>
        <translation>Textur &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file has a texture but no texture coordinates</source>
        <translation>die Datei hat eine Textur, aber keine Texturkoordinaten</translation>
    </message>
</context>
<context>
    <name>lb::Language</name>
    <message>
        <location filename="../../app/common/language.cpp" line="+48"/>
        <source>&amp;System</source>
        <extracomment>View &gt; Language: follow the system&apos;s language (LANG)</extracomment>
        <translation>&amp;System</translation>
    </message>
    <message>
        <location filename="../../app/window/language_menu.cpp" line="+21"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../../app/window/run_window.cpp" line="+142"/>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The window changes its language when lightbench starts again. Restart now?</source>
        <translation>Das Fenster wechselt die Sprache, wenn lightbench neu startet. Jetzt neu starten?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lightbench closes as it does on Quit, asking about unsaved work, and opens again where you were.</source>
        <translation>lightbench wird wie mit Beenden geschlossen (ungesicherte Arbeit wird erfragt) und öffnet sich wieder dort, wo Sie waren.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Restart &amp;Now</source>
        <translation>&amp;Jetzt neu starten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Later</source>
        <translation>&amp;Später</translation>
    </message>
    <message>
        <location filename="../../app/window/run_window.cpp" line="+1"/>
        <source>lightbench could not start again. Start it yourself to see the new language.</source>
        <translation>lightbench konnte nicht neu starten. Starten Sie es selbst, um die neue Sprache zu sehen.</translation>
    </message>
</context>
<context>
    <name>lb::Lesson</name>
    <message>
        <location filename="../../render/model/scene/lesson.cpp" line="-218"/>
        <source>%1 (%2)</source>
        <extracomment>a field of a lesson file (%1, &quot;step 2: caption.de&quot;) and why it was not used (%2)</extracomment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&quot;%1&quot; is not one of %2</source>
        <extracomment>%1 a word the file gave, %2 the words allowed (as files spell them)</extracomment>
        <translation>&quot;%1&quot; ist keiner der Werte %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a value that is not text is not one of %1</source>
        <translation>kein Text und damit keiner der Werte %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>%1: the scene file %2 (%3) is past what is left of the lesson&apos;s limit (%4 for the lesson and its scene files)</source>
        <extracomment>%1 the step (&quot;step 3&quot;), %2 a path, %3 its size, %4 the limit</extracomment>
        <translation>%1: Die Szenendatei %2 (%3) übersteigt, was von der Größengrenze der Lektion noch übrig ist (%4 für die Lektion und ihre Szenendateien)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: no scene (&quot;scene&quot; must be a scene object or the name of a scene file)</source>
        <translation>%1: keine Szene (&quot;scene&quot; muss ein Szenenobjekt oder der Name einer Szenendatei sein)</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>%1: not a lesson file: %2 at byte %3</source>
        <extracomment>%1 a path, %2 Qt&apos;s JSON parser&apos;s reason</extracomment>
        <translation>%1: keine Lektionsdatei: %2 bei Byte %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: a scene file, not a lesson (open it with File &gt; Open Scene)</source>
        <translation>%1: eine Szenendatei, keine Lektion (öffnen Sie sie mit Datei &gt; Szene öffnen)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: not a lesson file (&quot;format&quot; is not &quot;%2&quot;)</source>
        <translation>%1: keine Lektionsdatei (&quot;format&quot; ist nicht &quot;%2&quot;)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>missing or not a number; read as %1</source>
        <translation>fehlt oder ist keine Zahl; gelesen als %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>newer than this lightbench&apos;s %1: what it does not know is left out</source>
        <translation>neuer als Version %1, die dieses lightbench kennt: Unbekanntes wird ausgelassen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the lesson has no steps (&quot;steps&quot; must be a list of steps)</source>
        <translation>%1: Die Lektion hat keine Schritte (&quot;steps&quot; muss eine Liste von Schritten sein)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 steps; a lesson may have at most %3</source>
        <translation>%1: %2 Schritte; eine Lektion darf höchstens %3 haben</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>step %1</source>
        <extracomment>where in a lesson file a message is about: &quot;step 3: title (not text)&quot;</extracomment>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: not an object</source>
        <translation>%1: kein JSON-Objekt</translation>
    </message>
</context>
<context>
    <name>lb::LessonActions</name>
    <message>
        <location filename="../../app/window/lesson_actions.cpp" line="+43"/>
        <source>Open Recent &amp;Lesson</source>
        <translation>Zuletzt geöffnete Lekt&amp;ion</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The last lesson could not be opened again: %1</source>
        <translation>Die letzte Lektion konnte nicht erneut geöffnet werden: %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Open &amp;Lesson...</source>
        <translation>&amp;Lektion öffnen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lesso&amp;ns</source>
        <translation>Lektio&amp;nen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>(none built in)</source>
        <translation>(keine eingebaut)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Less&amp;on</source>
        <translation>&amp;Lektion</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Next Step</source>
        <translation>&amp;Nächster Schritt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Previous Step</source>
        <translation>&amp;Vorheriger Schritt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;First Step</source>
        <translation>&amp;Erster Schritt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Last Step</source>
        <translation>&amp;Letzter Schritt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset Step</source>
        <translation>Schritt &amp;zurücksetzen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New Lesson from This &amp;View</source>
        <translation>Neue Lektion aus dieser &amp;Ansicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Add This View as a Step</source>
        <translation>Diese Ansicht als Schritt &amp;hinzufügen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace the Step with &amp;This View</source>
        <translation>Schritt durch diese Ansicht e&amp;rsetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rena&amp;me Step...</source>
        <translation>Schritt u&amp;mbenennen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit &amp;Caption...</source>
        <translation>&amp;Beschriftung bearbeiten...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move Step &amp;Up</source>
        <translation>Schritt nach &amp;oben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move Step &amp;Down</source>
        <translation>Schritt nach un&amp;ten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remo&amp;ve Step</source>
        <translation>Schritt ent&amp;fernen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save Lesson</source>
        <translation>Lektion &amp;speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Lesson &amp;As...</source>
        <translation>Lektion speichern &amp;unter...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Close Lesson</source>
        <translation>Le&amp;ktion schließen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Caption &amp;Language</source>
        <translation>S&amp;prache der Beschriftung</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Same as the Window</source>
        <extracomment>Lesson &gt; Caption Language: the same language as the window&apos;s menus (View &gt; Language)</extracomment>
        <translation>Sprache des Fensters</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>untitled lesson</source>
        <translation>unbenannte Lektion</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The lesson could not be opened; nothing changed.</source>
        <translation>Die Lektion konnte nicht geöffnet werden; nichts wurde geändert.</translation>
    </message>
    <message numerus="yes">
        <location line="+22"/>
        <source>%1 opened; %n step(s) cannot be shown (the lesson bar says why there).</source>
        <translation>
            <numerusform>%1 geöffnet; %n Schritt kann nicht angezeigt werden (die Lektionsleiste nennt dort den Grund).</numerusform>
            <numerusform>%1 geöffnet; %n Schritte können nicht angezeigt werden (die Lektionsleiste nennt dort den Grund).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%1 opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>%1 geöffnet; %n Feld konnte nicht verwendet werden und behält seinen Standardwert.</numerusform>
            <numerusform>%1 geöffnet; %n Felder konnten nicht verwendet werden und behalten ihre Standardwerte.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+115"/>
        <location filename="../../app/window/lesson_authoring.cpp" line="+35"/>
        <location line="+34"/>
        <source>Step %1</source>
        <extracomment>a new step&apos;s title, until the teacher renames it (saved in the lesson file)</extracomment>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Open a lesson</source>
        <translation>Lektion öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lessons (*.lblesson *.json);;All files (*)</source>
        <translation>Lektionen (*.lblesson *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+9"/>
        <location filename="../../app/window/lesson_authoring.cpp" line="-37"/>
        <source>Lesson</source>
        <extracomment>a new lesson&apos;s title, until the teacher renames it (saved in the lesson file)</extracomment>
        <translation>Lektion</translation>
    </message>
    <message>
        <location filename="../../app/window/lesson_authoring.cpp" line="+26"/>
        <source>A lesson has at most %1 steps and this one has them all: the view was not added</source>
        <translation>Eine Lektion hat höchstens %1 Schritte, und diese hat sie alle: die Ansicht wurde nicht hinzugefügt</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>The step keeps its title.</source>
        <translation>Der Schritt behält seinen Titel.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A step&apos;s title cannot be empty.</source>
        <translation>Der Titel eines Schritts darf nicht leer sein.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The title has %1 characters; a title holds at most %2.</source>
        <translation>Der Titel hat %1 Zeichen; ein Titel fasst höchstens %2.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The step keeps its caption.</source>
        <translation>Der Schritt behält seine Beschriftung.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 caption has %2 characters; a caption holds at most %3.</source>
        <extracomment>%1: the caption&apos;s language code (en, de, pt)</extracomment>
        <translation>Die Beschriftung (%1) hat %2 Zeichen; eine Beschriftung fasst höchstens %3.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>The step stays.</source>
        <translation>Der Schritt bleibt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A lesson keeps at least one step; Close Lesson puts it away.</source>
        <translation>Eine Lektion behält mindestens einen Schritt; „Lektion schließen“ legt sie weg.</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>The lesson was not saved; it stays open with its changes.</source>
        <translation>Die Lektion wurde nicht gespeichert; sie bleibt mit ihren Änderungen geöffnet.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved the lesson to %1</source>
        <translation>Lektion gespeichert in %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Lessons (*.json)</source>
        <translation>Lektionen (*.json)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lightbench lessons (*.lblesson)</source>
        <translation>lightbench-Lektionen (*.lblesson)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the lesson</source>
        <translation>Lektion speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Rename Step</source>
        <translation>Schritt umbenennen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The title of step %1:</source>
        <translation>Titel von Schritt %1:</translation>
    </message>
</context>
<context>
    <name>lb::LessonBar</name>
    <message>
        <location filename="../../widgets/lesson_bar.cpp" line="+44"/>
        <source>The previous step (PageUp, Left)</source>
        <translation>Vorheriger Schritt (Bild auf, Links)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The next step (PageDown, Right, Space)</source>
        <translation>Nächster Schritt (Bild ab, Rechts, Leertaste)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reset Step</source>
        <translation>Schritt zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This step as the lesson has it: your changes to it are set aside</source>
        <translation>Dieser Schritt, wie ihn die Lektion enthält: Ihre Änderungen daran werden beiseitegelegt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The Lesson menu: add, rename, caption, move and save steps</source>
        <translation>Das Menü „Lektion“: Schritte hinzufügen, umbenennen, beschriften, verschieben und speichern</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Close the lesson (the scene stays)</source>
        <translation>Lektion schließen (die Szene bleibt)</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Step %1 of %2</source>
        <extracomment>where the class is in the lesson: step %1 of %2 steps</extracomment>
        <translation>Schritt %1 von %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>This step cannot be shown; the scene is as it was. %1</source>
        <translation>Dieser Schritt kann nicht angezeigt werden; die Szene bleibt, wie sie war. %1</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>[picture]</source>
        <extracomment>in a lesson&apos;s caption, where the markdown had an image (never shown there)</extracomment>
        <translation>[Bild]</translation>
    </message>
</context>
<context>
    <name>lb::LightPanel</name>
    <message>
        <location filename="../../widgets/light_panel.cpp" line="+40"/>
        <location line="+172"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location line="-169"/>
        <source>Up to four lights; their terms add up. A shader that declares one light (not an array) reads light 1</source>
        <translation>Bis zu vier Lichter; ihre Anteile addieren sich. Ein Shader, der nur ein Licht deklariert (kein Array), liest Licht 1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>On</source>
        <extracomment>the light is switched on (a check box)</extracomment>
        <translation>An</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uLightEnabled[i]: a light switched off adds nothing (its colours go to shaders as black)</source>
        <translation>uLightEnabled[i]: Ein ausgeschaltetes Licht trägt nichts bei (seine Farben gehen als Schwarz an die Shader)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Light</source>
        <extracomment>the row of the light&apos;s on/off switch</extracomment>
        <translation>Licht</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>w = 1: point light</source>
        <extracomment>w is the light position&apos;s 4th (homogeneous) coordinate: a symbol, not a word</extracomment>
        <translation>w = 1: Punktlicht</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>w = 0: directional</source>
        <translation>w = 0: gerichtet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lightPosition.w: 1 puts the light at (x, y, z); 0 makes (x, y, z) the direction towards a light at infinity</source>
        <translation>lightPosition.w: 1 setzt das Licht an (x, y, z); 0 macht (x, y, z) zur Richtung zu einem Licht im Unendlichen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Type</source>
        <extracomment>a light&apos;s type: point or directional</extracomment>
        <translation>Typ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Camera: moves with the eye</source>
        <translation>Kamera: bewegt sich mit dem Auge</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>World: fixed in the scene</source>
        <translation>Welt: fest in der Szene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Object: turns with the model</source>
        <translation>Objekt: dreht sich mit dem Modell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame lightPosition is given in. Camera: used as is (variant I); world: mView / mViewNormals (II); object: mModelView / mNormals (III)</source>
        <translation>Koordinatensystem, in dem lightPosition angegeben ist. Kamera: unverändert verwendet (Variante I); Welt: mView / mViewNormals (II); Objekt: mModelView / mNormals (III)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The object whose frame an object-frame light is given in: the light turns and moves with it, and lights every object from there</source>
        <translation>Das Objekt, in dessen Koordinaten ein Licht in Objektkoordinaten angegeben ist: Das Licht dreht und bewegt sich mit ihm und beleuchtet von dort aus jedes Objekt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Frame</source>
        <extracomment>the coordinate frame the light&apos;s position is given in</extracomment>
        <translation>Koordinaten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Of object</source>
        <extracomment>the object whose frame an object-frame light is given in</extracomment>
        <translation>Bezugsobjekt</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Atten. kc kl kq</source>
        <translation>Abschw. kc kl kq</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Spot axis</source>
        <translation>Spot-Achse</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Spot cutoff, exp</source>
        <extracomment>the spotlight&apos;s cutoff angle and exponent</extracomment>
        <translation>Spot-Winkel, Exp.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset light</source>
        <translation>Licht zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This light&apos;s defaults; light 1&apos;s are the slides&apos; (0, 1.8, 1.3, 1) in world coordinates</source>
        <translation>Die Standardwerte dieses Lichts; die von Licht 1 sind die der Folien: (0, 1.8, 1.3, 1) in Weltkoordinaten</translation>
    </message>
</context>
<context>
    <name>lb::LightingParameters</name>
    <message>
        <location filename="../../render/model/lighting/lighting_parameters.cpp" line="+16"/>
        <source>w must be 0 (directional) or 1 (point)</source>
        <translation>w muss 0 (gerichtet) oder 1 (Punkt) sein</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a directional light (w = 0) with the direction 0, 0, 0</source>
        <translation>ein gerichtetes Licht (w = 0) mit der Richtung 0, 0, 0</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>kc, kl and kq all 0 (the light would be infinite)</source>
        <translation>kc, kl und kq alle 0 (das Licht wäre unendlich hell)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a direction of length 0</source>
        <translation>eine Richtung der Länge 0</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>lightPosition.%1: the light&apos;s %1 in the chosen frame</source>
        <translation>lightPosition.%1: die %1-Koordinate des Lichts im gewählten Koordinatensystem</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 (%2): the light&apos;s ambient intensity</source>
        <extracomment>%1 the symbol (Ia, Id, Is); %2 the uniforms that carry it</extracomment>
        <translation>%1 (%2): die ambiente Intensität des Lichts</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (%2): the light&apos;s diffuse intensity</source>
        <translation>%1 (%2): die diffuse Intensität des Lichts</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (%2): the light&apos;s specular intensity</source>
        <translation>%1 (%2): die spiegelnde Intensität des Lichts</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>lightAttenuation.%1 (%2): a point light&apos;s terms are divided by kc + kl·d + kq·d², d its distance to the surface (1, 0, 0: none; a directional light is never attenuated)</source>
        <extracomment>%1 the axis (x, y, z); %2 its name (kc, kl, kq)</extracomment>
        <translation>lightAttenuation.%1 (%2): Die Anteile eines Punktlichts werden durch kc + kl·d + kq·d² geteilt, d ist sein Abstand zur Oberfläche (1, 0, 0: keine; ein gerichtetes Licht wird nie abgeschwächt)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>spotDirection.%1: the spotlight&apos;s axis, from the light, in the light&apos;s frame</source>
        <translation>spotDirection.%1: die Achse des Spotlichts, vom Licht aus, im Koordinatensystem des Lichts</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>spotCutoff: the cone&apos;s half-angle; outside it the light adds nothing, ambient included (180: no spot)</source>
        <translation>spotCutoff: der halbe Öffnungswinkel des Kegels; außerhalb trägt das Licht nichts bei, auch nicht ambient (180: kein Spot)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>spotExponent: inside the cone the terms are scaled by max(-L·D, 0)^exponent, brighter towards the axis</source>
        <translation>spotExponent: Innerhalb des Kegels werden die Anteile mit max(-L·D, 0)^exponent skaliert, zur Achse hin heller</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (%2): the material&apos;s ambient reflection coefficients</source>
        <extracomment>%1 the symbol (Ka, Kd, Ks); %2 the uniforms that carry it</extracomment>
        <translation>%1 (%2): die ambienten Reflexionskoeffizienten des Materials</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 (%2): the material&apos;s diffuse reflection coefficients</source>
        <translation>%1 (%2): die diffusen Reflexionskoeffizienten des Materials</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 (%2): the material&apos;s specular reflection coefficients</source>
        <translation>%1 (%2): die spiegelnden Reflexionskoeffizienten des Materials</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>shininess: the specular exponent n in (R.V)^n or (N.H)^n; higher gives a smaller, sharper highlight</source>
        <translation>shininess: der Glanzexponent n in (R.V)^n oder (N.H)^n; ein größerer Wert ergibt ein kleineres, schärferes Glanzlicht</translation>
    </message>
</context>
<context>
    <name>lb::LoadProgress</name>
    <message>
        <location filename="../../widgets/load_progress.cpp" line="+21"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop loading: the import helper is stopped, the current mesh stays</source>
        <translation>Laden abbrechen: Der Import-Helfer wird beendet, das aktuelle Mesh bleibt</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Loading %1...</source>
        <translation>%1 wird geladen...</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Loading %1: %2</source>
        <translation>%1 wird geladen: %2</translation>
    </message>
</context>
<context>
    <name>lb::LocalizedText</name>
    <message>
        <location filename="../../render/model/scene/localized_text.cpp" line="+29"/>
        <source>not text</source>
        <translation>kein Text</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 characters; at most %2</source>
        <translation>%1 Zeichen; höchstens %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a language code</source>
        <translation>kein Sprachcode</translation>
    </message>
</context>
<context>
    <name>lb::Loops</name>
    <message>
        <location filename="../../render/glsl/loop_messages.cpp" line="+18"/>
        <source>this loop runs %1 times for every fragment: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>diese Schleife läuft für jedes Fragment %1-mal: Ein Bild würde auf jeder GPU Sekunden oder länger dauern (llvmpipe bricht sie nach 65.535 Schritten ab und zeichnet ein falsches Bild)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this loop runs %1 times for every fragment (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>diese Schleife läuft für jedes Fragment %1-mal (ihr Zähler entfernt sich von seiner Grenze: nur ein Zahlenüberlauf beendet sie): Ein Bild würde auf jeder GPU Sekunden oder länger dauern (llvmpipe bricht sie nach 65.535 Schritten ab und zeichnet ein falsches Bild)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this loop runs %1 times for every vertex: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>diese Schleife läuft für jeden Vertex %1-mal: Ein Bild würde auf jeder GPU Sekunden oder länger dauern (llvmpipe bricht sie nach 65.535 Schritten ab und zeichnet ein falsches Bild)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this loop runs %1 times for every vertex (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>diese Schleife läuft für jeden Vertex %1-mal (ihr Zähler entfernt sich von seiner Grenze: nur ein Zahlenüberlauf beendet sie): Ein Bild würde auf jeder GPU Sekunden oder länger dauern (llvmpipe bricht sie nach 65.535 Schritten ab und zeichnet ein falsches Bild)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every fragment: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>dieses Programm stellt nie ein Bild fertig: Die Schleife hier läuft für jedes Fragment %1-mal: Ein Bild würde auf jeder GPU Sekunden oder länger dauern (llvmpipe bricht sie nach 65.535 Schritten ab und zeichnet ein falsches Bild)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every fragment (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>dieses Programm stellt nie ein Bild fertig: Die Schleife hier läuft für jedes Fragment %1-mal (ihr Zähler entfernt sich von seiner Grenze: nur ein Zahlenüberlauf beendet sie): Ein Bild würde auf jeder GPU Sekunden oder länger dauern (llvmpipe bricht sie nach 65.535 Schritten ab und zeichnet ein falsches Bild)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every vertex: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>dieses Programm stellt nie ein Bild fertig: Die Schleife hier läuft für jeden Vertex %1-mal: Ein Bild würde auf jeder GPU Sekunden oder länger dauern (llvmpipe bricht sie nach 65.535 Schritten ab und zeichnet ein falsches Bild)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every vertex (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>dieses Programm stellt nie ein Bild fertig: Die Schleife hier läuft für jeden Vertex %1-mal (ihr Zähler entfernt sich von seiner Grenze: nur ein Zahlenüberlauf beendet sie): Ein Bild würde auf jeder GPU Sekunden oder länger dauern (llvmpipe bricht sie nach 65.535 Schritten ab und zeichnet ein falsches Bild)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>this loop never ends: it has no condition and nothing in it breaks, returns or discards (the driver may drop it and draw garbage, or hang)</source>
        <translation>diese Schleife endet nie: Sie hat keine Bedingung, und nichts in ihr führt break, return oder discard aus (der Treiber kann sie verwerfen und Unsinn zeichnen oder hängen bleiben)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this loop never ends: its condition is always true and nothing in it breaks, returns or discards (the driver may drop it and draw garbage, or hang)</source>
        <translation>diese Schleife endet nie: Ihre Bedingung ist immer wahr, und nichts in ihr führt break, return oder discard aus (der Treiber kann sie verwerfen und Unsinn zeichnen oder hängen bleiben)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this program never finishes a frame: the loop here has no condition (or an always-true one) and no break, return or discard</source>
        <translation>dieses Programm stellt nie ein Bild fertig: Die Schleife hier hat keine Bedingung (oder eine immer wahre) und kein break, return oder discard</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>this loop never ends once it starts: its condition reads %1, and nothing in the loop changes it</source>
        <extracomment>%1 the names the loop&apos;s condition reads, as the shader spells them (&quot;i, n&quot;)</extracomment>
        <translation>diese Schleife endet nie, sobald sie einmal läuft: Ihre Bedingung liest %1, und nichts in der Schleife ändert diesen Wert</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this loop never ends once it starts: its condition reads %1, and nothing in the loop changes them</source>
        <translation>diese Schleife endet nie, sobald sie einmal läuft: Ihre Bedingung liest %1, und nichts in der Schleife ändert diese Werte</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 (the loop comes from macro %2, used on this line)</source>
        <extracomment>%1 a message about a loop, %2 the name of the macro that writes the loop</extracomment>
        <translation>%1 (die Schleife stammt aus dem Makro %2, das in dieser Zeile verwendet wird)</translation>
    </message>
</context>
<context>
    <name>lb::MacroExpansion</name>
    <message>
        <location filename="../../render/glsl/macro_expansion.cpp" line="+94"/>
        <source>macro %1 expands through more than %2 macros, one inside another: refused before the driver sees it</source>
        <translation>Makro %1 expandiert über mehr als %2 ineinander verschachtelte Makros: abgelehnt, bevor der Treiber es sieht</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>macro %1 expands to more than a million tokens (a macro that doubles itself?): refused before the driver sees it</source>
        <translation>Makro %1 expandiert zu mehr als einer Million Tokens (ein Makro, das sich selbst verdoppelt?): abgelehnt, bevor der Treiber es sieht</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>macro %1 expands to more than 1 MB of text (a macro that doubles itself?): refused before the driver sees it</source>
        <translation>Makro %1 expandiert zu mehr als 1 MB Text (ein Makro, das sich selbst verdoppelt?): abgelehnt, bevor der Treiber es sieht</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>macro %1 calls macros inside macro arguments more than %2 deep: refused before the driver sees it</source>
        <translation>Makro %1 ruft Makros in Makroargumenten mehr als %2 Ebenen tief auf: abgelehnt, bevor der Treiber es sieht</translation>
    </message>
</context>
<context>
    <name>lb::MainWindow</name>
    <message>
        <location filename="../../app/window/main_window.cpp" line="+85"/>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shading</source>
        <translation>Schattierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Uniforms</source>
        <translation>Uniforms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bindings</source>
        <translation>Bindungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Probe</source>
        <translation>Sonde</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Shader editor</source>
        <translation>Shader-Editor</translation>
    </message>
    <message>
        <location line="+40"/>
        <location filename="../../app/window/main_window_menus.cpp" line="+53"/>
        <location filename="../../app/window/main_window_unsaved.cpp" line="+92"/>
        <location line="+13"/>
        <source>Shader files</source>
        <translation>Shader-Dateien</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Unsaved shader edits from the last session are back</source>
        <translation>Ungespeicherte Shader-Änderungen aus der letzten Sitzung sind wieder da</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Everything reset; Ctrl+Z in the editor brings your shader text back</source>
        <translation>Alles zurückgesetzt; Strg+Z im Editor holt Ihren Shader-Text zurück</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Everything reset</source>
        <translation>Alles zurückgesetzt</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The program on screen computes V = (0,0,1), the parallel view vector, under the perspective projection; the reference uses V = -P, so the two differ away from the middle of the view. The orthographic projection (key P) makes them agree.</source>
        <translation>Das Programm auf dem Bildschirm berechnet unter perspektivischer Projektion V = (0,0,1), den Blickvektor der Parallelprojektion; die Referenz verwendet V = -P, daher weichen beide abseits der Bildmitte voneinander ab. Die orthografische Projektion (Taste P) bringt sie in Übereinstimmung.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 shades as it is written: Gouraud/Phong does not change it. A preset or Reset Everything brings the built-in program, which follows this choice.</source>
        <translation>%1 schattiert so, wie es geschrieben ist: Gouraud/Phong ändert daran nichts. Eine Vorlage oder „Alles zurücksetzen“ lädt das eingebaute Programm, das dieser Wahl folgt.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The program in the editor (%1) shades Gouraud (per vertex) whatever this says. Load a preset or Reset Everything to switch shading.</source>
        <translation>Das Programm im Editor (%1) schattiert nach Gouraud (pro Vertex), egal was hier steht. Laden Sie eine Vorlage oder wählen Sie „Alles zurücksetzen“, um die Schattierung umzuschalten.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The program in the editor (%1) shades Phong (per fragment) whatever this says. Load a preset or Reset Everything to switch shading.</source>
        <translation>Das Programm im Editor (%1) schattiert nach Phong (pro Fragment), egal was hier steht. Laden Sie eine Vorlage oder wählen Sie „Alles zurücksetzen“, um die Schattierung umzuschalten.</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1, step %2</source>
        <translation>%1, Schritt %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1[*] - lightbench</source>
        <translation>%1[*] - lightbench</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_budget.cpp" line="+44"/>
        <source>More would take more memory than the scene&apos;s meshes may take on this machine: %1 for all objects together.</source>
        <translation>Mehr bräuchte mehr Speicher, als die Meshes der Szene auf diesem Rechner belegen dürfen: %1 für alle Objekte zusammen.</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_exercise.cpp" line="+72"/>
        <source>Check cancelled.</source>
        <translation>Prüfung abgebrochen.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Checked: %1 of %2 cases pass</source>
        <translation>Geprüft: %1 von %2 Fällen bestanden</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>Not checked: %1</source>
        <extracomment>a check that graded nothing, for a reason this version does not know (%1, in English)</extracomment>
        <translation>Nicht geprüft: %1</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>Side B</source>
        <translation>Seite B</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not checked: does not compile</source>
        <translation>Nicht geprüft: lässt sich nicht kompilieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: does not link</source>
        <translation>Nicht geprüft: lässt sich nicht linken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: refused</source>
        <translation>Nicht geprüft: abgelehnt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: timed out</source>
        <translation>Nicht geprüft: Zeitüberschreitung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: could not start</source>
        <translation>Nicht geprüft: konnte nicht starten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: crashed</source>
        <translation>Nicht geprüft: abgestürzt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: unreadable</source>
        <translation>Nicht geprüft: nicht lesbar</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+2"/>
        <source>Not checked: the exercise has a broken mistake</source>
        <translation>Nicht geprüft: Die Übung enthält einen fehlerhaften bekannten Fehler</translation>
    </message>
    <message>
        <location line="+83"/>
        <location line="+16"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>the exercise&apos;s reference</source>
        <translation>die Referenz der Übung</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>the exercise&apos;s reference (built-in)</source>
        <translation>die Referenz der Übung (eingebaut)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+39"/>
        <source>the built-in program</source>
        <translation>das eingebaute Programm</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>side B (%1)</source>
        <translation>Seite B (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Side B draws %1: it shades as it is written, so these choices do nothing. The x button brings back %2.</source>
        <translation>Seite B zeichnet %1: Dieses Programm schattiert so, wie es geschrieben ist, daher bewirken diese Einstellungen nichts. Die Schaltfläche x holt %2 zurück.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Side B draws the exercise&apos;s reference program: it shades as it is written, so these choices do nothing.</source>
        <translation>Seite B zeichnet das Referenzprogramm der Übung: Es schattiert so, wie es geschrieben ist, daher bewirken diese Einstellungen nichts.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the exercise&apos;s reference (built-in, %1 shading, %2 specular)</source>
        <extracomment>%1: gouraud, phong or flat; %2: phong or blinn</extracomment>
        <translation>die Referenz der Übung (eingebaut, Schattierung %1, spiegelnder Anteil %2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the built-in program, %1 shading and %2 specular (the exercise&apos;s reference)</source>
        <extracomment>%1: gouraud, phong or flat; %2: phong or blinn</extracomment>
        <translation>das eingebaute Programm, Schattierung %1 und spiegelnder Anteil %2 (die Referenz der Übung)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The exercise&apos;s reference fixes side B&apos;s choices.</source>
        <translation>Die Referenz der Übung legt die Einstellungen von Seite B fest.</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Side B is unchanged: %1</source>
        <translation>Seite B bleibt unverändert: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Side B is unchanged: %1 does not build:
%2</source>
        <translation>Seite B bleibt unverändert: %1 lässt sich nicht erstellen:
%2</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Side B: a shader pair (NAME.vert or NAME.frag) or a scene file&apos;s program</source>
        <translation>Seite B: ein Shader-Paar (NAME.vert oder NAME.frag) oder das Programm einer Szenendatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shader pairs and scene files (*.vert *.frag *.json *.lbscene);;All files (*)</source>
        <translation>Shader-Paare und Szenendateien (*.vert *.frag *.json *.lbscene);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The check could not start: %1</source>
        <translation>Die Prüfung konnte nicht starten: %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Case %1 in the difference view (key C: the other compare views; &quot;Back to my scene&quot; in the Exercise panel)</source>
        <extracomment>&quot;Back to my scene&quot; is the Exercise panel&apos;s button: its name as translated there</extracomment>
        <translation>Fall %1 in der Differenzansicht (Taste C: die anderen Vergleichsansichten; „Zurück zu meiner Szene“ im Bereich „Übung“)</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_menus.cpp" line="-13"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Chec&amp;k My Work</source>
        <translation>&amp;Arbeit prüfen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>F9</source>
        <translation>F9</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Side B: Shader Files...</source>
        <translation>Seite B: Shader-Dateien...</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../../app/window/main_window_unsaved.cpp" line="-5"/>
        <source>Shader pairs (*.vert *.frag);;All files (*)</source>
        <translation>Shader-Paare (*.vert *.frag);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open S&amp;haders...</source>
        <translation>S&amp;hader öffnen...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a shader pair (NAME.vert and NAME.frag)</source>
        <translation>Shader-Paar öffnen (NAME.vert und NAME.frag)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save Shaders</source>
        <translation>Shader speichern</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Alt+S</source>
        <translation>Ctrl+Alt+S</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Shaders As...</source>
        <translation>Shader speichern unter...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <extracomment>the menu (camera, probe, zoom, presentation, docks), not the 3D view itself</extracomment>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reset &amp;Everything</source>
        <translation>Alles zu&amp;rücksetzen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+R</source>
        <translation>Ctrl+Shift+R</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Undo in the Editor</source>
        <translation>&amp;Rückgängig im Editor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Redo in the Editor</source>
        <translation>&amp;Wiederherstellen im Editor</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <source>Ctrl+Y</source>
        <translation>Ctrl+Y</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Find in the Shader</source>
        <translation>Im Shader &amp;suchen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Shading</source>
        <translation>&amp;Schattierung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Toggle &amp;Gouraud / Phong</source>
        <translation>&amp;Gouraud / Phong umschalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>G</source>
        <comment>shortcut</comment>
        <translation>G</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>P</source>
        <comment>shortcut</comment>
        <translation>P</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>L</source>
        <comment>shortcut</comment>
        <translation>L</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>C</source>
        <comment>shortcut</comment>
        <translation>C</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>R</source>
        <comment>shortcut</comment>
        <translation>R</translation>
    </message>
    <message>
        <location line="-53"/>
        <source>Toggle Phong / &amp;Blinn-Phong specular</source>
        <translation>Spiegelnden Anteil Phong / &amp;Blinn-Phong umschalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+B</source>
        <translation>Ctrl+B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The program in the editor (%1) computes its own specular term: load a preset or Reset Everything to switch it.</source>
        <translation>Das Programm im Editor (%1) berechnet seinen eigenen spiegelnden Anteil: Laden Sie eine Vorlage oder wählen Sie „Alles zurücksetzen“, um ihn umzuschalten.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Toggle &amp;Perspective / Orthographic</source>
        <translation>&amp;Perspektivisch / orthografisch umschalten</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Toggle &amp;Lighting</source>
        <translation>Be&amp;leuchtung ein/aus</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Toggle the &amp;Ambient Term</source>
        <translation>&amp;Ambienten Anteil ein/aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toggle the &amp;Diffuse Term</source>
        <translation>&amp;Diffusen Anteil ein/aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toggle the &amp;Specular Term</source>
        <translation>&amp;Spiegelnden Anteil ein/aus</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A</source>
        <comment>shortcut</comment>
        <translation>A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>D</source>
        <comment>shortcut</comment>
        <translation>D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S</source>
        <comment>shortcut</comment>
        <translation>S</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Compare: Off / Side by Side / Wipe / Difference</source>
        <translation>&amp;Vergleich: Aus / Nebeneinander / Wischblende / Differenz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Reset Camera</source>
        <translation>&amp;Kamera zurücksetzen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clear the &amp;Probe (in Presentation Mode: Leave It)</source>
        <translation>&amp;Sonde entfernen (im Präsentationsmodus: diesen verlassen)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Esc</source>
        <translation>Esc</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Auto-rotate</source>
        <translation>Automatisch d&amp;rehen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Space</source>
        <translation>Space</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Features (README)</source>
        <translation>&amp;Funktionen (README)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About lightbench</source>
        <translation>Ü&amp;ber lightbench</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Zoom &amp;In Editor</source>
        <translation>Editor &amp;vergrößern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+=</source>
        <translation>Ctrl+=</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom &amp;Out Editor</source>
        <translation>Editor verk&amp;leinern</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reset Editor &amp;Zoom</source>
        <translation>Editor-&amp;Zoom zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>UI &amp;Scale</source>
        <translation>&amp;Oberflächenskalierung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1%</source>
        <extracomment>View &gt; UI Scale: a size in percent (&quot;125%&quot;)</extracomment>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Fit the &amp;Window to the Screen</source>
        <translation>&amp;Fenster an den Bildschirm anpassen</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_presentation.cpp" line="+54"/>
        <source>&amp;Presentation Mode</source>
        <translation>&amp;Präsentationsmodus</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>F11</source>
        <translation>F11</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>F5</source>
        <translation>F5</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Shift+F5</source>
        <translation>Shift+F5</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Full screen, the presentation UI scale, the view large (F6: the panels)</source>
        <translation>Vollbild, die Oberflächenskalierung der Präsentation, die Ansicht groß (F6: die Bereiche)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the Panels in Presentation &amp;Mode</source>
        <translation>Bereiche im Präsentations&amp;modus zeigen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>F6</source>
        <translation>F6</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Blank the Screen (Presentation Mode)</source>
        <translation>Bildschirm sch&amp;warz schalten (Präsentationsmodus)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B</source>
        <comment>shortcut</comment>
        <translation>B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Faded Probe Arrows</source>
        <translation>&amp;Blasse Sondenpfeile</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The probe&apos;s arrows thin and see-through, so the highlight under them stays visible</source>
        <translation>Die Pfeile der Sonde dünn und durchscheinend, damit das Glanzlicht darunter sichtbar bleibt</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>B or . blanks the screen in presentation mode (F5 or F11); Phong / Blinn-Phong is Ctrl+B</source>
        <translation>B oder . schaltet den Bildschirm im Präsentationsmodus (F5 oder F11) schwarz; Phong / Blinn-Phong ist Strg+B</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Presentation mode (F5) will show the panels (F6 hides them)</source>
        <translation>Der Präsentationsmodus (F5) zeigt die Bereiche an (F6 blendet sie aus)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Presentation mode (F5) will hide the panels (F6 shows them)</source>
        <translation>Der Präsentationsmodus (F5) blendet die Bereiche aus (F6 zeigt sie an)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The editor needs %1 px at this scale: View &gt; Shader editor shows it</source>
        <extracomment>View &gt; Shader editor: the menu&apos;s and the dock&apos;s names as translated there</extracomment>
        <translation>Der Editor braucht bei dieser Skalierung %1 px: Ansicht &gt; Shader-Editor zeigt ihn</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_unsaved.cpp" line="-1"/>
        <source>Save the shader pair as NAME.vert and NAME.frag</source>
        <translation>Shader-Paar als NAME.vert und NAME.frag speichern</translation>
    </message>
</context>
<context>
    <name>lb::MaterialPanel</name>
    <message>
        <location filename="../../widgets/material_panel.cpp" line="+68"/>
        <source>Shininess</source>
        <translation>Glanzexponent</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset material</source>
        <translation>Material zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The selected object&apos;s material back to the slides&apos; red plastic: Ka = Kd = (1, 0, 0), Ks = (1, 1, 1), n = 6</source>
        <translation>Das Material des ausgewählten Objekts zurück auf das rote Plastik der Folien: Ka = Kd = (1, 0, 0), Ks = (1, 1, 1), n = 6</translation>
    </message>
</context>
<context>
    <name>lb::MeshActions</name>
    <message>
        <location filename="../../app/window/mesh_actions.cpp" line="+68"/>
        <source>Open &amp;Recent Mesh</source>
        <translation>Zuletzt geöffnetes M&amp;esh</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Texture not used</source>
        <translation>Textur nicht verwendet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>An image could not be used as a texture.</source>
        <translation>Ein Bild konnte nicht als Textur verwendet werden.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Mesh not built</source>
        <translation>Mesh nicht erstellt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An object&apos;s mesh could not be built; it keeps what it drew before.</source>
        <translation>Das Mesh eines Objekts konnte nicht erstellt werden; es behält, was es vorher gezeichnet hat.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Open &amp;Mesh...</source>
        <translation>&amp;Mesh öffnen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+M</source>
        <translation>Ctrl+M</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open &amp;Texture Image...</source>
        <translation>&amp;Texturbild öffnen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+T</source>
        <translation>Ctrl+T</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Preferences...</source>
        <translation>&amp;Einstellungen...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ctrl+,</source>
        <translation>Ctrl+,</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;Normals</source>
        <translation>&amp;Normalen anzeigen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>N</source>
        <comment>shortcut</comment>
        <translation>N</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 not loaded (%2 drawn)</source>
        <extracomment>%1: the mesh file; %2: the built-in shape drawn instead (cube, sphere, ...)</extracomment>
        <translation>%1 nicht geladen (%2 gezeichnet)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 triangles, %3 s</source>
        <translation>%1: %2 Dreiecke, %3 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 triangles</source>
        <translation>%1: %2 Dreiecke</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+4"/>
        <location line="+11"/>
        <source>%1; %2</source>
        <extracomment>a mesh&apos;s short summary (%1) and what was turned in it or why it draws nothing (%2: &quot;faces turned: ...&quot;, &quot;draws nothing in view: ...&quot;)</extracomment>
        <translation>%1; %2</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Meshes Assimp reads (%1);;</source>
        <translation>Von Assimp lesbare Meshes (%1);;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open a mesh</source>
        <translation>Mesh öffnen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Open an image as the selected object&apos;s texture</source>
        <translation>Bild als Textur des ausgewählten Objekts öffnen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Images (%1);;All files (*)</source>
        <translation>Bilder (%1);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Mesh not loaded</source>
        <translation>Mesh nicht geladen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A mesh file the scene names could not be loaded. Its objects draw their shapes and keep its name, so saving keeps it; it is read again after the file changes (at your next change to the scene) or when you open it.</source>
        <translation>Eine Mesh-Datei, die die Szene nennt, konnte nicht geladen werden. Ihre Objekte zeichnen ihre Grundform und behalten den Dateinamen, sodass er beim Speichern erhalten bleibt; die Datei wird erneut gelesen, wenn sie sich ändert (bei Ihrer nächsten Änderung an der Szene) oder wenn Sie sie öffnen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The mesh could not be loaded; the previous one stays.</source>
        <translation>Das Mesh konnte nicht geladen werden; das vorherige bleibt.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Files not used</source>
        <translation>Dateien nicht verwendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Some files could not be used.</source>
        <translation>Einige Dateien konnten nicht verwendet werden.</translation>
    </message>
</context>
<context>
    <name>lb::MeshFile</name>
    <message>
        <location filename="../../render/model/mesh/mesh_file.cpp" line="+41"/>
        <source>%1 points, lines or broken faces skipped</source>
        <translation>%1 Punkte, Linien oder defekte Flächen übersprungen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 vertices with non-finite coordinates dropped, with the %2 triangles using them</source>
        <translation>%1 Vertices mit nicht endlichen Koordinaten entfernt, samt der %2 Dreiecke, die sie verwenden</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 normals with non-finite coordinates: the file&apos;s normals not used</source>
        <translation>%1 Normalen mit nicht endlichen Koordinaten: Die Normalen der Datei werden nicht verwendet</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: %2 vertices, %3 triangles</source>
        <translation>%1: %2 Vertices, %3 Dreiecke</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s</source>
        <translation>%1: %2 Vertices, %3 Dreiecke, geladen in %4 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s, normals generated</source>
        <translation>%1: %2 Vertices, %3 Dreiecke, geladen in %4 s, Normalen erzeugt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s, normals generated (the file has none)</source>
        <translation>%1: %2 Vertices, %3 Dreiecke, geladen in %4 s, Normalen erzeugt (die Datei hat keine)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (%2)</source>
        <extracomment>a mesh&apos;s summary (%1) and what was skipped or not used in its file (%2, a list)</extracomment>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>lb::MeshOrientation</name>
    <message>
        <location filename="../../render/model/mesh/mesh_orientation.cpp" line="+246"/>
        <source>faces turned: the file winds them clockwise</source>
        <translation>Flächen gewendet: die Datei ordnet sie im Uhrzeigersinn an</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>faces of %1 of %2 closed parts turned: the file winds them clockwise</source>
        <translation>Flächen von %1 der %2 geschlossenen Teile gewendet: die Datei ordnet sie im Uhrzeigersinn an</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>normals turned: the file&apos;s point inwards</source>
        <translation>Normalen gewendet: die der Datei zeigen nach innen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>normals of %1 of %2 closed parts turned: the file&apos;s point inwards</source>
        <translation>Normalen von %1 der %2 geschlossenen Teile gewendet: die der Datei zeigen nach innen</translation>
    </message>
</context>
<context>
    <name>lb::MessageText</name>
    <message>
        <location filename="../../render/model/io/message_text.cpp" line="+85"/>
        <source>... and %1 more</source>
        <translation>... und %1 weitere</translation>
    </message>
</context>
<context>
    <name>lb::NumberBox</name>
    <message>
        <location filename="../../widgets/number_box.cpp" line="+68"/>
        <source>Not a number: digits, a sign in front and one decimal separator.</source>
        <translation>Keine Zahl: Ziffern, ein Vorzeichen vorne und ein Dezimaltrennzeichen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A whole number, typed without separators.</source>
        <translation>Eine ganze Zahl, ohne Trennzeichen eingegeben.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One decimal separator, a point or a comma (2.5 or 2,5), and no thousands separators.</source>
        <translation>Ein Dezimaltrennzeichen, Punkt oder Komma (2.5 oder 2,5), und keine Tausendertrennzeichen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This box takes whole numbers.</source>
        <translation>Dieses Feld nimmt ganze Zahlen an.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>This box takes %n decimal(s).</source>
        <translation>
            <numerusform>Dieses Feld nimmt %n Nachkommastelle an.</numerusform>
            <numerusform>Dieses Feld nimmt %n Nachkommastellen an.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This box takes %1 to %2.</source>
        <extracomment>%1 the lowest number the box takes, %2 the highest (with their units)</extracomment>
        <translation>Dieses Feld nimmt Werte von %1 bis %2 an.</translation>
    </message>
</context>
<context>
    <name>lb::ObjectLoader</name>
    <message>
        <location filename="../../render/import/object_loader_textures.cpp" line="+67"/>
        <source>%1 (the objects naming it show the mesh file&apos;s texture or the checker, and keep its name for when the file is back)</source>
        <translation>%1 (die Objekte, die diese Datei nennen, zeigen die Textur der Mesh-Datei oder das Schachbrettmuster und behalten den Dateinamen für den Fall, dass die Datei wieder da ist)</translation>
    </message>
    <message>
        <location filename="../../render/import/object_loader.cpp" line="+173"/>
        <source>%1: not used: its object was removed</source>
        <translation>%1: nicht verwendet: sein Objekt wurde entfernt</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>%1: not loaded: cancelled</source>
        <translation>%1: nicht geladen: abgebrochen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: not loaded: its object was removed</source>
        <translation>%1: nicht geladen: sein Objekt wurde entfernt</translation>
    </message>
    <message>
        <location filename="../../app/window/mesh_actions.cpp" line="-25"/>
        <location filename="../../render/import/object_loader.cpp" line="+2"/>
        <location line="+186"/>
        <source>Loading cancelled</source>
        <translation>Laden abgebrochen</translation>
    </message>
    <message>
        <location filename="../../render/import/object_loader.cpp" line="-62"/>
        <source>building</source>
        <translation>wird erstellt</translation>
    </message>
</context>
<context>
    <name>lb::ObjectMesh</name>
    <message>
        <location filename="../../render/model/mesh/object_mesh.cpp" line="+34"/>
        <source>out of memory building %1&apos;s normals (%2 triangles)</source>
        <translation>nicht genug Speicher zum Erzeugen der Normalen von %1 (%2 Dreiecke)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of memory building the cube</source>
        <translation>nicht genug Speicher zum Erstellen des Würfels</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>out of memory building the sphere at tessellation %1</source>
        <translation>nicht genug Speicher zum Erstellen der Kugel mit Tessellierung %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>out of memory building the torus at tessellation %1</source>
        <translation>nicht genug Speicher zum Erstellen des Torus mit Tessellierung %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>out of memory building the plane at tessellation %1</source>
        <translation>nicht genug Speicher zum Erstellen der Ebene mit Tessellierung %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+103"/>
        <source>out of memory building a mesh</source>
        <translation>nicht genug Speicher zum Erstellen eines Meshes</translation>
    </message>
</context>
<context>
    <name>lb::ObjectPanel</name>
    <message>
        <location filename="../../widgets/object_panel.cpp" line="+31"/>
        <source>The scene&apos;s objects, each with its own mesh, transform and material: select one to edit it here and in the Material panel (or click it in the view). Untick to hide; double-click to rename</source>
        <translation>Die Objekte der Szene, jedes mit eigenem Mesh, eigener Transformation und eigenem Material: Wählen Sie eines aus, um es hier und im Bereich „Material“ zu bearbeiten (oder klicken Sie es in der Ansicht an). Haken entfernen zum Ausblenden; Doppelklick zum Umbenennen</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new sphere in the first free place near the centre (at most %1 objects; R frames them all)</source>
        <translation>Eine neue Kugel am ersten freien Platz nahe der Mitte (höchstens %1 Objekte; R bringt alle ins Bild)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A copy of the selected object, material and all, in the first free place near the centre</source>
        <translation>Eine Kopie des ausgewählten Objekts samt Material am ersten freien Platz nahe der Mitte</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 copy</source>
        <translation>%1 - Kopie</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Removes the selected object (the last one stays); lights in its frame go to the object before it</source>
        <translation>Entfernt das ausgewählte Objekt (das letzte bleibt); Lichter in seinen Objektkoordinaten gehen an das Objekt davor</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cube (flat faces)</source>
        <translation>Würfel (flache Seiten)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Sphere (smooth)</source>
        <translation>Kugel (glatt)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Torus</source>
        <translation>Torus</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The object: vPosition and vNormal come from this mesh. A built-in shape replaces a mesh file</source>
        <translation>Das Objekt: vPosition und vNormal kommen aus diesem Mesh. Eine eingebaute Form ersetzt eine Mesh-Datei</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Open...</source>
        <translation>Öffnen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a mesh file: any format Assimp reads (Ctrl+M; or drop a file on the window)</source>
        <translation>Mesh-Datei öffnen: jedes Format, das Assimp liest (Strg+M; oder eine Datei auf dem Fenster ablegen)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Subdivisions of the sphere, torus and plane. Few vertices show Gouraud&apos;s weakness: its highlight follows the vertices</source>
        <translation>Unterteilungen von Kugel, Torus und Ebene. Wenige Vertices zeigen die Schwäche von Gouraud: Das Glanzlicht folgt den Vertices</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Tessellation</source>
        <translation>Tessellierung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From the mesh</source>
        <translation>Aus dem Mesh</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Smooth (crease angle)</source>
        <translation>Glatt (Knickwinkel)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flat</source>
        <translation>Flach</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vNormal: the mesh&apos;s own normals (generated smooth when a file has none), or generated: smooth, averaged over the triangles around a vertex within the crease angle, or flat, one per triangle</source>
        <translation>vNormal: die eigenen Normalen des Meshes (glatt erzeugt, wenn eine Datei keine hat) oder erzeugt: glatt, gemittelt über die Dreiecke um einen Vertex innerhalb des Knickwinkels, oder flach, eine pro Dreieck</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Normals</source>
        <translation>Normalen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outward</source>
        <translation>Nach außen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>As in the file</source>
        <translation>Wie in der Datei</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flipped</source>
        <translation>Umgedreht</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Both sides lit</source>
        <translation>Beide Seiten beleuchtet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which way a mesh file&apos;s faces look. Outward: a closed part wound inwards (lit from inside) is turned, with its normals, and the status line says so; as in the file; every face flipped; or both sides lit, each with the normal facing the camera (for open meshes: a sheet, a scan with holes)</source>
        <translation>Wohin die Flächen einer Mesh-Datei schauen. Nach außen: ein geschlossener Teil, der nach innen zeigt (von innen beleuchtet), wird samt Normalen gewendet, und die Statuszeile sagt es; wie in der Datei; jede Fläche umgedreht; oder beide Seiten beleuchtet, jede mit der Normalen zur Kamera (für offene Meshes: eine Fläche, ein Scan mit Löchern)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Faces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Generated smooth normals average only triangles that meet at less than this angle: 0 is flat, 180 smooths every edge</source>
        <translation>Erzeugte glatte Normalen mitteln nur über Dreiecke, die sich unter weniger als diesem Winkel treffen: 0 ist flach, 180 glättet jede Kante</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Crease angle</source>
        <translation>Knickwinkel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show normals as lines</source>
        <translation>Normalen als Linien zeigen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A short line along each vertex normal, transformed by mNormals as the shaders do (key N)</source>
        <translation>Eine kurze Linie entlang jeder Vertex-Normale, transformiert mit mNormals wie in den Shadern (Taste N)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cull back faces (closed meshes)</source>
        <translation>Rückseiten ausblenden (geschlossene Meshes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Triangles facing away from the camera are not drawn: the same picture for a closed mesh, about twice as fast; an open mesh shows holes where its inside was</source>
        <translation>Von der Kamera abgewandte Dreiecke werden nicht gezeichnet: bei einem geschlossenen Mesh dasselbe Bild, etwa doppelt so schnell; ein offenes Mesh zeigt Löcher, wo seine Innenseite war</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Use the mesh file&apos;s material</source>
        <translation>Material der Mesh-Datei verwenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The mesh file&apos;s ambient, diffuse and specular colours and shininess replace Ka, Kd, Ks and shininess: now, and whenever a file is loaded</source>
        <translation>Die ambiente, diffuse und spiegelnde Farbe und der Glanzexponent der Mesh-Datei ersetzen Ka, Kd, Ks und den Glanzexponenten: jetzt und bei jedem Laden einer Datei</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Rotation about %1 in degrees (model matrix; applied X, then Y, then Z)</source>
        <translation>Drehung um %1 in Grad (Modellmatrix; angewendet X, dann Y, dann Z)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Scale along %1. A non-uniform scale is why normals need mNormals, the inverse transpose of mModelView</source>
        <translation>Skalierung entlang %1. Eine ungleichmäßige Skalierung ist der Grund, warum Normalen mNormals brauchen, die inverse Transponierte von mModelView</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Translation along world %1: where the object&apos;s centre lies (model matrix, applied last)</source>
        <translation>Verschiebung entlang der Welt-%1-Achse: wo der Mittelpunkt des Objekts liegt (Modellmatrix, zuletzt angewendet)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Rotate</source>
        <extracomment>the row of the object&apos;s rotation about X, Y and Z</extracomment>
        <translation>Drehen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scale</source>
        <extracomment>the row of the object&apos;s scale along X, Y and Z</extracomment>
        <translation>Skalieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move</source>
        <extracomment>the row of the object&apos;s translation along X, Y and Z</extracomment>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Auto-rotate about Y</source>
        <translation>Automatisch um Y drehen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turns the model: a light in the object frame turns with it (key Space)</source>
        <translation>Dreht das Modell: Ein Licht in Objektkoordinaten dreht sich mit (Leertaste)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reset object</source>
        <translation>Objekt zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The selected object back to the coarse unit sphere, unrotated, unscaled and not turning; its name, place and material stay</source>
        <translation>Das ausgewählte Objekt zurück zur groben Einheitskugel, nicht gedreht, nicht skaliert und ohne automatische Drehung; Name, Ort und Material bleiben</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>File: %1</source>
        <extracomment>the shape combo&apos;s entry for a mesh file; %1 the file&apos;s name</extracomment>
        <translation>Datei: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File: %1 (not loaded)</source>
        <translation>Datei: %1 (nicht geladen)</translation>
    </message>
</context>
<context>
    <name>lb::Offscreen</name>
    <message>
        <location filename="../../render/gl/offscreen.cpp" line="+49"/>
        <source>cannot create an OpenGL context (is there an X server with OpenGL?)</source>
        <translation>OpenGL-Kontext kann nicht erstellt werden (gibt es einen X-Server mit OpenGL?)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cannot make the OpenGL context current</source>
        <translation>OpenGL-Kontext kann nicht aktiviert werden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>OpenGL 3.3 is needed, the driver gives %1.%2</source>
        <translation>OpenGL 3.3 wird benötigt, der Treiber bietet %1.%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>cannot create a %1x%2 framebuffer</source>
        <translation>Framebuffer der Größe %1x%2 kann nicht erstellt werden</translation>
    </message>
</context>
<context>
    <name>lb::PlotChart</name>
    <message>
        <location filename="../../widgets/plot_chart.cpp" line="+175"/>
        <source>Angle between R and V (°)</source>
        <translation>Winkel zwischen R und V (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle between N and L (°)</source>
        <translation>Winkel zwischen N und L (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance d from the light</source>
        <translation>Abstand d vom Licht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle from the spot&apos;s axis (°)</source>
        <translation>Winkel zur Achse des Spots (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specular factor</source>
        <translation>Faktor des spiegelnden Anteils</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot factor</source>
        <translation>Spotfaktor</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Surface</source>
        <translation>Oberfläche</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Specular factor&lt;br&gt;&lt;small&gt;Phong (R·V)^n, Blinn-Phong (N·H)^n; dashed: Blinn-Phong at 4n&lt;/small&gt;</source>
        <translation>Faktor des spiegelnden Anteils&lt;br&gt;&lt;small&gt;Phong (R·V)^n, Blinn-Phong (N·H)^n; gestrichelt: Blinn-Phong mit 4n&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Diffuse factor&lt;br&gt;&lt;small&gt;against the angle of incidence&lt;/small&gt;</source>
        <translation>Diffuser Faktor&lt;br&gt;&lt;small&gt;über dem Einfallswinkel&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Attenuation&lt;br&gt;&lt;small&gt;against the distance from the light&lt;/small&gt;</source>
        <translation>Abschwächung&lt;br&gt;&lt;small&gt;über dem Abstand vom Licht&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Spotlight factor&lt;br&gt;&lt;small&gt;against the angle from its axis&lt;/small&gt;</source>
        <translation>Spotfaktor&lt;br&gt;&lt;small&gt;über dem Winkel zur Achse&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The three terms as V sweeps&lt;br&gt;&lt;small&gt;the plane of incidence, N up; radius: the mean of red, green and blue&lt;/small&gt;</source>
        <translation>Die drei Anteile, während V&lt;br&gt;&lt;small&gt;die Einfallsebene überstreicht, N oben; Radius: Mittelwert aus Rot, Grün und Blau&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>No point light is on: a directional light (w = 0) is not attenuated.</source>
        <translation>Kein Punktlicht ist an: ein gerichtetes Licht (w = 0) wird nicht abgeschwächt.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No spotlight: every light that is on has a cutoff of 180°. Set a cutoff in the Light panel.</source>
        <translation>Kein Spotlicht: jedes eingeschaltete Licht hat einen Öffnungswinkel von 180°. Stellen Sie im Bereich „Licht“ einen kleineren ein.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No light is on.</source>
        <translation>Kein Licht ist an.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No lobe: the light is at the surface&apos;s point, where L has no direction. Move the light off the surface.</source>
        <translation>Keine Keule: das Licht liegt im Punkt der Oberfläche, wo L keine Richtung hat. Rücken Sie das Licht von der Oberfläche weg.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Ambient</source>
        <translation>Ambient</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse</source>
        <translation>Diffus</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Specular</source>
        <translation>Spiegelnd</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
</context>
<context>
    <name>lb::PlotsPanel</name>
    <message>
        <location filename="../../widgets/plots_panel.cpp" line="+42"/>
        <source>Specular: Phong and Blinn-Phong</source>
        <translation>Spiegelnd: Phong und Blinn-Phong</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diffuse: max(N·L, 0)</source>
        <translation>Diffus: max(N·L, 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attenuation with distance</source>
        <translation>Abschwächung mit dem Abstand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spotlight falloff</source>
        <translation>Abfall des Spotlichts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lobe at the probed point</source>
        <translation>Keule am gemessenen Punkt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which of the model&apos;s curves to draw</source>
        <translation>Welche Kurve des Modells gezeichnet wird</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write this plot as a PNG or SVG picture, or its samples as CSV</source>
        <translation>Dieses Diagramm als PNG- oder SVG-Bild oder seine Stützstellen als CSV schreiben</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>No point probed: light %1&apos;s lobe where N faces the camera at the selected object&apos;s centre. Ctrl+click the surface to plot it at a point.</source>
        <translation>Kein Punkt gemessen: die Keule von Licht %1 dort, wo N in der Mitte des ausgewählten Objekts zur Kamera zeigt. Strg+Klick auf die Oberfläche zeichnet sie an einem Punkt.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Ctrl+click the surface: the probed point&apos;s own values appear as dots.</source>
        <translation>Strg+Klick auf die Oberfläche: die Werte des gemessenen Punkts erscheinen als Punkte.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light %1&apos;s terms at the probed point. The dots are where V&apos;s part in the plane of incidence points; the Probe tab has the values at V itself.</source>
        <translation>Die Anteile von Licht %1 am gemessenen Punkt. Die Punkte liegen dort, wohin V innerhalb der Einfallsebene zeigt; die Werte genau bei V stehen im Bereich „Sonde“.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No dot: at the probed point every light is behind the surface (N·L &lt; 0) or outside the plot.</source>
        <translation>Kein Punkt: am gemessenen Punkt liegt jedes Licht hinter der Oberfläche (N·L &lt; 0) oder außerhalb des Diagramms.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Dots: each light&apos;s angle at the probed point (for Blinn-Phong, 2·acos(N·H)).</source>
        <translation>Punkte: der Winkel jedes Lichts am gemessenen Punkt (bei Blinn-Phong 2·acos(N·H)).</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SVG pictures (*.svg)</source>
        <translation>SVG-Bilder (*.svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV samples (*.csv)</source>
        <translation>CSV-Stützstellen (*.csv)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+15"/>
        <source>Export the plot</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The plot could not be written; nothing was changed.
%1</source>
        <translation>Das Diagramm konnte nicht geschrieben werden; nichts wurde geändert.
%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported the plot to %1</source>
        <translation>Diagramm exportiert nach %1</translation>
    </message>
</context>
<context>
    <name>lb::PreferencesDialog</name>
    <message>
        <location filename="../../widgets/preferences_dialog.cpp" line="+15"/>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mesh files are read by a helper process (lightbench-import). When it needs more memory or time than this, it is stopped and the file gets a message; the workbench carries on.</source>
        <translation>Mesh-Dateien werden von einem Hilfsprozess (lightbench-import) gelesen. Braucht er mehr Speicher oder Zeit als hier angegeben, wird er beendet und die Datei erhält eine Meldung; die Werkbank arbeitet weiter.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source> MB</source>
        <extracomment>megabytes, after the number</extracomment>
        <translation> MB</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The helper&apos;s address-space limit. Default: half of this machine&apos;s memory (%1 MB). Also --import-memory-limit MB</source>
        <translation>Die Adressraum-Grenze des Hilfsprozesses. Standard: die Hälfte des Arbeitsspeichers dieses Rechners (%1 MB). Auch --import-memory-limit MB</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Import memory limit</source>
        <translation>Speichergrenze für den Import</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+9"/>
        <source> s</source>
        <extracomment>seconds, after the number</extracomment>
        <translation> s</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>A load that takes longer is stopped. Default: %1 s</source>
        <translation>Ein Ladevorgang, der länger dauert, wird abgebrochen. Standard: %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import time limit</source>
        <translation>Zeitgrenze für den Import</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Your shader program is tried on tiny frames before it draws; when one frame at the view&apos;s size would take longer than this, it is refused and the last good program keeps drawing. Default: %1 s. Also --frame-budget SECONDS</source>
        <translation>Ihr Shader-Programm wird vor dem Zeichnen an winzigen Bildern erprobt; würde ein Bild in der Größe der Ansicht länger dauern als hier angegeben, wird es abgelehnt und das letzte funktionierende Programm zeichnet weiter. Standard: %1 s. Auch --frame-budget SECONDS</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Frame budget</source>
        <translation>Zeitbudget pro Bild</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move the camera and the lights smoothly between a lesson&apos;s steps</source>
        <translation>Kamera und Lichter zwischen den Schritten einer Lektion fließend bewegen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>So the class sees where they go; off: each step jumps</source>
        <translation>Damit die Klasse sieht, wohin sie sich bewegen; aus: jeder Schritt springt</translation>
    </message>
</context>
<context>
    <name>lb::Presets</name>
    <message>
        <location filename="../../render/glsl/presets.cpp" line="+37"/>
        <source>Built-in: Phong shading (per fragment)</source>
        <translation>Eingebaut: Phong-Schattierung (pro Fragment)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Built-in: Gouraud shading (per vertex)</source>
        <translation>Eingebaut: Gouraud-Schattierung (pro Vertex)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Slides: Gouraud, WebGL 1 as printed</source>
        <translation>Folien: Gouraud, WebGL 1 wie abgedruckt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Slides: Phong shading, WebGL 1 as printed</source>
        <translation>Folien: Phong-Schattierung, WebGL 1 wie abgedruckt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Toon (the exercise&apos;s &quot;like Zelda&quot;), GLSL 3.30</source>
        <translation>Toon („wie Zelda“ aus der Übung), GLSL 3.30</translation>
    </message>
</context>
<context>
    <name>lb::ProbeEquation</name>
    <message>
        <location filename="../../render/model/measure/probe_equation.cpp" line="+150"/>
        <source>Lighting is off: the surface shows Kd times the base colour instead.</source>
        <translation>Beleuchtung aus: Die Oberfläche zeigt stattdessen Kd mal die Grundfarbe.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Flat shading draws the model at the triangle&apos;s last (provoking) vertex, one colour for the triangle; these numbers are the model at this point.</source>
        <translation>Flache Schattierung wertet das Modell am letzten (provozierenden) Vertex des Dreiecks aus, eine Farbe für das ganze Dreieck; diese Zahlen geben das Modell an diesem Punkt wieder.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Gouraud shading draws the model at the triangle&apos;s vertices, interpolated; these numbers are the model at this point.</source>
        <translation>Gouraud-Schattierung wertet das Modell an den Vertices des Dreiecks aus und interpoliert dazwischen; diese Zahlen geben das Modell an diesem Punkt wieder.</translation>
    </message>
    <message>
        <location line="-72"/>
        <source>(base multiplies ambient and diffuse only)</source>
        <extracomment>after the equation in symbols, where a texture&apos;s base colour multiplies it</extracomment>
        <translation>(base multipliziert nur den ambienten und den diffusen Anteil)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>(0: the light is behind the surface)</source>
        <extracomment>after the specular term&apos;s numbers, where N·L &lt; 0</extracomment>
        <translation>(0: das Licht liegt hinter der Oberfläche)</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>[off]</source>
        <extracomment>before a term the Shading panel switched off</extracomment>
        <translation>[aus]</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>light %1: %2</source>
        <extracomment>a light&apos;s line of the equation: %1 its number, %2 its factors (att·spot = ...)</extracomment>
        <translation>Licht %1: %2</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>pixel = %1 of 255 (clamped to 0..1)</source>
        <extracomment>%1 the pixel&apos;s red, green and blue, as (r, g, b)</extracomment>
        <translation>Pixel = %1 von 255 (auf 0..1 begrenzt)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The surface shows %1, not this colour.</source>
        <extracomment>%1 what the Shading panel&apos;s Show choice draws instead (normal, ndotl, ...)</extracomment>
        <translation>Die Oberfläche zeigt statt dieser Farbe: %1.</translation>
    </message>
</context>
<context>
    <name>lb::ProbePanel</name>
    <message>
        <location filename="../../widgets/probe_panel.cpp" line="+68"/>
        <source>Copy the Equation</source>
        <translation>Gleichung kopieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The lighting equation with this point&apos;s numbers, as text</source>
        <translation>Die Beleuchtungsgleichung mit den Zahlen dieses Punkts, als Text</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Ctrl+click (or Shift+click) the surface to probe a point: the vectors, N·L, the specular angle and the three terms, beside the pixel the GPU drew. Esc clears it.</source>
        <translation>Strg+Klick (oder Umschalt+Klick) auf die Oberfläche misst einen Punkt mit der Sonde: die Vektoren, N·L, den Winkel des spiegelnden Anteils und die drei Anteile, neben dem Pixel, das die GPU gezeichnet hat. Esc entfernt ihn.</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>No surface at (%1, %2).</source>
        <translation>Keine Oberfläche bei (%1, %2).</translation>
    </message>
    <message>
        <location line="+107"/>
        <source>pixel (%1, %2), %3, triangle %4</source>
        <extracomment>%1, %2 the pixel; %3 the object&apos;s name; %4 the triangle&apos;s number</extracomment>
        <translation>Pixel (%1, %2), %3, Dreieck %4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pixel (%1, %2), %3, triangle %4, side B</source>
        <translation>Pixel (%1, %2), %3, Dreieck %4, Seite B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pixel (%1, %2), %3, triangle %4, side A</source>
        <translation>Pixel (%1, %2), %3, Dreieck %4, Seite A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>P (eye)</source>
        <extracomment>P, the probed point, in eye coordinates</extracomment>
        <translation>P (Kamera)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>levels %1 and %2 (%3% of %2)</source>
        <translation>Stufen %1 und %2 (%3 % von %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>level %1</source>
        <translation>Stufe %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>uv (%1, %2), level of detail %3: %4, mipmaps</source>
        <extracomment>%1, %2 the texture coordinates; %3 the level of detail; %4 the mipmap levels read</extracomment>
        <translation>uv (%1, %2), Detailstufe %3: %4, Mipmaps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uv (%1, %2), level of detail %3: %4, no mipmaps</source>
        <translation>uv (%1, %2), Detailstufe %3: %4, ohne Mipmaps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>texture</source>
        <translation>Textur</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>base colour</source>
        <translation>Grundfarbe</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (%2 frame)</source>
        <extracomment>%1 the light&apos;s name in bold (Light 2); %2 its frame (camera, world, object)</extracomment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>P, L (%1)</source>
        <extracomment>P and L in the light&apos;s own frame: %1 the frame (world, object)</extracomment>
        <translation>P, L (%1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>distance, attenuation</source>
        <translation>Abstand, Abschwächung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 (outside the cone)</source>
        <translation>0 (außerhalb des Kegels)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (off)</source>
        <translation>%1 (aus)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+5"/>
        <source>ambient</source>
        <translation>ambient</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+5"/>
        <source>diffuse</source>
        <translation>diffus</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+5"/>
        <source>specular</source>
        <translation>spiegelnd</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Sum</source>
        <translation>Summe</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the model (%1 shading)</source>
        <translation>das Modell (Schattierung %1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 of 255 (the built-in model, %2 shading)</source>
        <extracomment>%1 the colour (r, g, b) of 255; %2 the shading (gouraud, phong, flat)</extracomment>
        <translation>%1 von 255 (das eingebaute Modell, Schattierung %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of 255 (%2 shading)</source>
        <translation>%1 von 255 (Schattierung %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+3"/>
        <source>reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 draws nothing here</source>
        <translation>%1 zeichnet hier nichts</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>%1 draws %2</source>
        <extracomment>%1 the reference&apos;s name; %2 its colour (r, g, b) at the point</extracomment>
        <translation>%1 zeichnet %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>GPU drew</source>
        <translation>GPU zeichnete</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>difference</source>
        <translation>Differenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of 255 from %2</source>
        <translation>%1 von 255 (Vergleich: %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 of 255</source>
        <translation>%1 von 255</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The equation at this point</source>
        <translation>Die Gleichung an diesem Punkt</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>This point is drawn by %1 (side B), which is itself the reference: it is compared with nothing. The numbers above are the built-in model&apos;s, which that program need not follow.</source>
        <translation>Diesen Punkt zeichnet %1 (Seite B), und Seite B ist selbst die Referenz: Er wird mit nichts verglichen. Die Zahlen oben stammen aus dem eingebauten Modell, dem dieses Programm nicht folgen muss.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The pixel is compared with what %1 draws at this point; the numbers above are the built-in model&apos;s.</source>
        <translation>Das Pixel wird mit dem verglichen, was %1 an diesem Punkt zeichnet; die Zahlen oben stammen aus dem eingebauten Modell.</translation>
    </message>
</context>
<context>
    <name>lb::Program</name>
    <message>
        <location filename="../../render/gl/program.cpp" line="+75"/>
        <source>the vertex shader is empty</source>
        <translation>der Vertex-Shader ist leer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fragment shader is empty</source>
        <translation>der Fragment-Shader ist leer</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the vertex shader is %1 KiB; lightbench compiles sources up to %2 KiB</source>
        <translation>der Vertex-Shader ist %1 KiB groß; lightbench kompiliert Quelltexte bis %2 KiB</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the fragment shader is %1 KiB; lightbench compiles sources up to %2 KiB</source>
        <translation>der Fragment-Shader ist %1 KiB groß; lightbench kompiliert Quelltexte bis %2 KiB</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>the vertex shader does not compile (the driver gave no reason)</source>
        <translation>der Vertex-Shader lässt sich nicht kompilieren (der Treiber nennt keinen Grund)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the fragment shader does not compile (the driver gave no reason)</source>
        <translation>der Fragment-Shader lässt sich nicht kompilieren (der Treiber nennt keinen Grund)</translation>
    </message>
    <message>
        <location line="+285"/>
        <source>the program does not link (no reason given)</source>
        <translation>das Programm lässt sich nicht linken (kein Grund angegeben)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no position input: the mesh reaches the shader through the attribute at layout(location = 0), or one named aPos, a_position, vPosition, aVertexPosition or position, or with pos or vert in its name</source>
        <translation>keine Positionseingabe: Das Mesh gelangt über das Attribut an layout(location = 0) in den Shader, oder über eines namens aPos, a_position, vPosition, aVertexPosition oder position, oder mit pos oder vert im Namen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the fragment shader writes no colour: assign gl_FragColor (no #version, #version 100) or declare an out vec4 (#version 300 es, 330 and later)</source>
        <translation>der Fragment-Shader schreibt keine Farbe: Weisen Sie gl_FragColor zu (ohne #version, #version 100) oder deklarieren Sie ein out vec4 (#version 300 es, 330 und neuer)</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>a global variable initialised from a uniform or another variable: GLSL ES 1.00 asks for a constant, browsers run it (WebGL warns); lightbench runs this program translated to GLSL 3.30 (the driver said: %1)</source>
        <translation>eine globale Variable, die aus einer Uniform oder einer anderen Variable initialisiert wird: GLSL ES 1.00 verlangt eine Konstante, Browser führen es aus (WebGL warnt); lightbench führt dieses Programm nach GLSL 3.30 übersetzt aus (der Treiber sagte: %1)</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+88"/>
        <source>built-in shader &apos;%1&apos; failed:
%2</source>
        <extracomment>%1 a built-in program&apos;s name, %2 its build log</extracomment>
        <translation>eingebauter Shader &apos;%1&apos; fehlgeschlagen:
%2</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>built-in shader &apos;%1&apos; lacks a &apos;#define MAX_LIGHTS&apos;, &apos;LIGHT_FACTORS&apos; or &apos;SHOW_CHOICES&apos; line
</source>
        <translation>dem eingebauten Shader &apos;%1&apos; fehlt eine Zeile &apos;#define MAX_LIGHTS&apos;, &apos;LIGHT_FACTORS&apos; oder &apos;SHOW_CHOICES&apos;
</translation>
    </message>
</context>
<context>
    <name>lb::ProgramGuard</name>
    <message>
        <location filename="../../render/pipeline/program_guard.cpp" line="+16"/>
        <source>the driver ran out of memory compiling or drawing this program (limit %1): a macro that doubles itself, or a program too big for it?</source>
        <translation>dem Treiber ging beim Kompilieren oder Zeichnen dieses Programms der Speicher aus (Grenze %1): ein Makro, das sich selbst verdoppelt, oder ein Programm, das zu groß für ihn ist?</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>compiling this program and drawing it on small frames took more than %1: an endless or very long loop, or a program too big for the driver?</source>
        <translation>das Kompilieren dieses Programms und das Zeichnen kleiner Testbilder dauerte länger als %1: eine Endlosschleife oder sehr lange Schleife, oder ein Programm, das zu groß für den Treiber ist?</translation>
    </message>
</context>
<context>
    <name>lb::ProgramTrial</name>
    <message>
        <location filename="../../render/pipeline/program_trial.cpp" line="+26"/>
        <source>%1 s</source>
        <extracomment>a duration in seconds</extracomment>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 ms</source>
        <extracomment>a duration in milliseconds</extracomment>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>drawing one frame with this program at %1x%2 would take more than its budget of %3: an endless or very long loop?</source>
        <extracomment>%1x%2 the frame&apos;s size in pixels, %3 the budget of one frame (&quot;2.0 s&quot;)</extracomment>
        <translation>ein Bild mit diesem Programm bei %1x%2 zu zeichnen würde länger dauern als sein Budget von %3: eine Endlosschleife oder sehr lange Schleife?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>drawing one frame with this program at %1x%2 would take more than its budget of %3: too much work for every pixel?</source>
        <translation>ein Bild mit diesem Programm bei %1x%2 zu zeichnen würde länger dauern als sein Budget von %3: zu viel Rechenarbeit pro Pixel?</translation>
    </message>
</context>
<context>
    <name>lb::RecentFiles</name>
    <message>
        <location filename="../../widgets/recent_files.cpp" line="+55"/>
        <source>(none yet)</source>
        <translation>(noch keine)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Clear the list</source>
        <translation>Liste leeren</translation>
    </message>
</context>
<context>
    <name>lb::SafeWrite</name>
    <message>
        <location filename="../../render/model/io/safe_write.cpp" line="+57"/>
        <location line="+14"/>
        <source>a loop of symbolic links</source>
        <translation>eine Schleife symbolischer Links</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not a regular file (a device, a pipe or a folder); not replaced</source>
        <translation>keine reguläre Datei (ein Gerät, eine Pipe oder ein Ordner); nicht ersetzt</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>read-only (mode %1); not replaced</source>
        <translation>schreibgeschützt (Modus %1); nicht ersetzt</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the folder %1 does not exist</source>
        <translation>der Ordner %1 existiert nicht</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is not a folder</source>
        <translation>%1 ist kein Ordner</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot write in %1: %2</source>
        <translation>in %1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="+127"/>
        <source>no image to write</source>
        <translation>kein Bild zum Schreiben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the PNG could not be encoded</source>
        <translation>das PNG konnte nicht kodiert werden</translation>
    </message>
</context>
<context>
    <name>lb::Scene</name>
    <message>
        <location filename="../../render/model/scene/scene.cpp" line="+391"/>
        <source>cube</source>
        <translation>Würfel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>torus</source>
        <translation>Torus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>plane</source>
        <translation>Ebene</translation>
    </message>
</context>
<context>
    <name>lb::SceneActions</name>
    <message>
        <location filename="../../app/window/scene_actions.cpp" line="+34"/>
        <source>Scenes (*.lbscene *.json);;All files (*)</source>
        <translation>Szenen (*.lbscene *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Scenes (*.json)</source>
        <translation>Szenen (*.json)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lightbench scenes (*.lbscene)</source>
        <translation>lightbench-Szenen (*.lbscene)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Open Recent S&amp;cene</source>
        <translation>&amp;Zuletzt geöffnete Szene</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Gouraud vs Phong (the slides)</source>
        <translation>Gouraud vs. Phong (aus den Folien)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phong vs Blinn-Phong specular</source>
        <translation>Spiegelnder Anteil: Phong vs. Blinn-Phong</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The three light frames</source>
        <translation>Die drei Koordinatensysteme des Lichts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The normal matrix</source>
        <translation>Die Normalenmatrix</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toon shading</source>
        <translation>Toon-Schattierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The terms one at a time (keys A, D, S)</source>
        <translation>Die Anteile einzeln (Tasten A, D, S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attenuation of a point light</source>
        <translation>Abschwächung eines Punktlichts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A spotlight</source>
        <translation>Ein Spotlicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The exercise: a textured cube and a sphere, light in camera coordinates</source>
        <translation>Die Übung: ein texturierter Würfel und eine Kugel, Licht in Kamerakoordinaten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A light in one object&apos;s frame (it turns with the torus)</source>
        <translation>Ein Licht in den Objektkoordinaten eines Objekts (es dreht sich mit dem Torus)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture filtering: nearest, linear and mipmaps</source>
        <translation>Texturfilterung: nächster Nachbar, linear und Mipmaps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exercise: per-fragment lighting (Check My Work, F9)</source>
        <translation>Übung: Beleuchtung pro Fragment (Arbeit prüfen, F9)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Open Scene...</source>
        <translation>Szene ö&amp;ffnen...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>E&amp;xamples</source>
        <translation>Beis&amp;piele</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Save Scene</source>
        <translation>Szene &amp;speichern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save Scene &amp;As...</source>
        <translation>Szene speichern &amp;unter...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>E&amp;xport Image...</source>
        <translation>Bild e&amp;xportieren...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cop&amp;y Image</source>
        <translation>Bild &amp;kopieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The scene could not be opened; nothing changed.</source>
        <translation>Die Szene konnte nicht geöffnet werden; nichts wurde geändert.</translation>
    </message>
    <message numerus="yes">
        <location line="+41"/>
        <source>%n field(s) could not be used and kept their defaults:</source>
        <translation>
            <numerusform>%n Feld konnte nicht verwendet werden und behält seinen Standardwert:</numerusform>
            <numerusform>%n Felder konnten nicht verwendet werden und behalten ihre Standardwerte:</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This step opened with less tessellation than it asks for, to fit this machine&apos;s memory; the file is unchanged unless you save the scene.</source>
        <translation>Dieser Schritt wurde mit geringerer Tessellierung als angefordert geöffnet, passend zum Speicher dieses Rechners; die Datei bleibt unverändert, solange Sie die Szene nicht speichern.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 opened with less tessellation than it asks for, to fit this machine&apos;s memory; the file is unchanged unless you save the scene.</source>
        <translation>%1 wurde mit geringerer Tessellierung als angefordert geöffnet, passend zum Speicher dieses Rechners; die Datei bleibt unverändert, solange Sie die Szene nicht speichern.</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>This step opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>Dieser Schritt wurde geöffnet; %n Feld konnte nicht verwendet werden und behält seinen Standardwert.</numerusform>
            <numerusform>Dieser Schritt wurde geöffnet; %n Felder konnten nicht verwendet werden und behalten ihre Standardwerte.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>%1 geöffnet; %n Feld konnte nicht verwendet werden und behält seinen Standardwert.</numerusform>
            <numerusform>%1 geöffnet; %n Felder konnten nicht verwendet werden und behalten ihre Standardwerte.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Opened the scene %1</source>
        <translation>Szene %1 geöffnet</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The scene was not saved.</source>
        <translation>Die Szene wurde nicht gespeichert.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved the scene to %1</source>
        <translation>Szene gespeichert in %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: not drawn: %2</source>
        <translation>%1: nicht gezeichnet: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the view could not be drawn at %2 x %3</source>
        <translation>%1: Die Ansicht konnte nicht in %2 x %3 gezeichnet werden</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The image was not exported.</source>
        <translation>Das Bild wurde nicht exportiert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Copied the view (%1 x %2) to the clipboard</source>
        <translation>Ansicht (%1 x %2) in die Zwischenablage kopiert</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Open a scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Save the scene</source>
        <translation>Szene speichern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export the view</source>
        <translation>Ansicht exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PNG images (*.png);;All files (*)</source>
        <translation>PNG-Bilder (*.png);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
</context>
<context>
    <name>lb::SceneBudget</name>
    <message>
        <location filename="../../render/model/mesh/scene_budget.cpp" line="+60"/>
        <location line="+2"/>
        <source>%1 million</source>
        <translation>%1 Millionen</translation>
    </message>
    <message numerus="yes">
        <location line="+15"/>
        <source>%n object(s) at tessellation %1 would make %2 triangles (~%3)</source>
        <extracomment>what a scene asks for; %n the objects in the scene</extracomment>
        <translation>
            <numerusform>%n Objekt mit Tessellierung %1 ergäbe %2 Dreiecke (~%3)</numerusform>
            <numerusform>%n Objekte mit Tessellierung %1 ergäben %2 Dreiecke (~%3)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n object(s) at tessellation up to %1 would make %2 triangles (~%3)</source>
        <translation>
            <numerusform>%n Objekt mit Tessellierung bis %1 ergäbe %2 Dreiecke (~%3)</numerusform>
            <numerusform>%n Objekte mit Tessellierung bis %1 ergäben %2 Dreiecke (~%3)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>tessellation lowered to %1 on %n object(s) (%2) to fit %3, the most a scene may take on this machine (%4 of memory): %5 triangles now</source>
        <extracomment>what was done about it; %n the objects lowered, %2 their names</extracomment>
        <translation>
            <numerusform>Tessellierung bei %n Objekt (%2) auf %1 gesenkt, um unter %3 zu bleiben (das Maximum für eine Szene auf diesem Rechner mit %4 Arbeitsspeicher): jetzt %5 Dreiecke</numerusform>
            <numerusform>Tessellierung bei %n Objekten (%2) auf %1 gesenkt, um unter %3 zu bleiben (das Maximum für eine Szene auf diesem Rechner mit %4 Arbeitsspeicher): jetzt %5 Dreiecke</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>tessellation lowered to %1 on %n object(s) (%2) and still over %3, the most a scene may take on this machine (%4 of memory): ~%5 (its mesh files count in full)</source>
        <translation>
            <numerusform>Tessellierung bei %n Objekt (%2) auf %1 gesenkt und trotzdem über %3 (das Maximum für eine Szene auf diesem Rechner mit %4 Arbeitsspeicher): ~%5 (die Mesh-Dateien der Szene zählen voll)</numerusform>
            <numerusform>Tessellierung bei %n Objekten (%2) auf %1 gesenkt und trotzdem über %3 (das Maximum für eine Szene auf diesem Rechner mit %4 Arbeitsspeicher): ~%5 (die Mesh-Dateien der Szene zählen voll)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1; %2</source>
        <extracomment>what a scene asked for (%1) and what was lowered to fit it in memory (%2)</extracomment>
        <translation>%1; %2</translation>
    </message>
    <message>
        <location line="+105"/>
        <source>%1 GB</source>
        <translation>%1 GB</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 MB</source>
        <translation>%1 MB</translation>
    </message>
</context>
<context>
    <name>lb::SceneFile</name>
    <message>
        <location filename="../../render/model/scene/scene_file.cpp" line="-161"/>
        <source>not true or false; read as false</source>
        <translation>nicht true oder false; als false gelesen</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>%1: not a scene file: %2 at byte %3</source>
        <extracomment>%1 a path, %2 Qt&apos;s JSON parser&apos;s reason</extracomment>
        <translation>%1: keine Szenendatei: %2 bei Byte %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: not a scene file: the JSON is not an object</source>
        <translation>%1: keine Szenendatei: Das JSON ist kein Objekt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: a lesson file, not a scene file (open it as a lesson)</source>
        <translation>%1: eine Lektionsdatei, keine Szenendatei (als Lektion öffnen)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>expected &quot;%1&quot;</source>
        <translation>erwartet: &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>missing or not a number; read as %1</source>
        <translation>fehlt oder ist keine Zahl; gelesen als %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>newer than this lightbench&apos;s %1: what it does not know is left out</source>
        <translation>neuer als Version %1, die dieses lightbench kennt: Unbekanntes wird ausgelassen</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>needs vertex and fragment sources as strings</source>
        <translation>braucht Vertex- und Fragment-Quelltext als Zeichenketten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the vertex shader has %1 characters, more than a shader may have (%2)</source>
        <extracomment>%1 the shader&apos;s characters; %2 the most a shader may have</extracomment>
        <translation>der Vertex-Shader hat %1 Zeichen, mehr als ein Shader haben darf (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the fragment shader has %1 characters, more than a shader may have (%2)</source>
        <extracomment>%1 the shader&apos;s characters; %2 the most a shader may have</extracomment>
        <translation>der Fragment-Shader hat %1 Zeichen, mehr als ein Shader haben darf (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not an object</source>
        <translation>kein JSON-Objekt</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 (the section is kept as it is)</source>
        <extracomment>%1 why an exercise section cannot be graded against</extracomment>
        <translation>%1 (der Abschnitt bleibt unverändert erhalten)</translation>
    </message>
</context>
<context>
    <name>lb::SceneJson</name>
    <message>
        <location filename="../../render/model/scene/scene_json.cpp" line="+230"/>
        <source>not one of the values the scene feeds (%1)</source>
        <translation>keiner der Werte, die die Szene speist (%1)</translation>
    </message>
    <message>
        <location line="+76"/>
        <location line="+33"/>
        <source>not an array</source>
        <translation>kein Array</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>at most 4 lights</source>
        <translation>höchstens 4 Lichter</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../../render/model/scene/scene_json_reader.cpp" line="+24"/>
        <source>not an object</source>
        <translation>kein JSON-Objekt</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>empty: one object drawn instead</source>
        <translation>leer: stattdessen wird ein Objekt gezeichnet</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>at most 32 objects; the rest left out</source>
        <translation>höchstens 32 Objekte; der Rest wird ausgelassen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not an object; a sphere in its place</source>
        <translation>kein JSON-Objekt; an seiner Stelle eine Kugel</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>no such object; the first one</source>
        <translation>dieses Objekt gibt es nicht; stattdessen das erste</translation>
    </message>
    <message>
        <location line="-159"/>
        <location line="+187"/>
        <source>too many: %1 more than the %2 kept</source>
        <translation>zu viele: %1 mehr als die %2 übernommenen</translation>
    </message>
    <message>
        <location line="-180"/>
        <location line="+187"/>
        <source>not a uniform&apos;s name</source>
        <translation>kein gültiger Uniform-Name</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>not 1 to 4 numbers</source>
        <translation>nicht 1 bis 4 Zahlen</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/scene_json_reader.cpp" line="-9"/>
        <source>%1 (%2)</source>
        <extracomment>a field of a scene file as the file spells it (%1, &quot;lights[2].frame&quot;, never translated) and why it was not used (%2)</extracomment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>unknown field</source>
        <translation>unbekanntes Feld</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+49"/>
        <source>not a number</source>
        <translation>keine Zahl</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not an array of numbers</source>
        <translation>kein Array von Zahlen</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+9"/>
        <source>out of range, clamped</source>
        <translation>außerhalb des zulässigen Bereichs, auf die Grenze gesetzt</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not true or false</source>
        <translation>nicht true oder false</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not a string</source>
        <translation>keine Zeichenkette</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+0"/>
        <source>not a whole number</source>
        <translation>keine ganze Zahl</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>unknown value</source>
        <translation>unbekannter Wert</translation>
    </message>
</context>
<context>
    <name>lb::ScenePanel</name>
    <message>
        <location filename="../../widgets/scene_panel.cpp" line="+84"/>
        <source>%1 or %2</source>
        <extracomment>uniform names, one of which a shader may declare: %1 the first ones, comma-separated; %2 the last</extracomment>
        <translation>%1 oder %2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Unused: the program on screen has no uniform %1 (a constant in the shader, perhaps), so this control changes nothing.

%2</source>
        <translation>Ungenutzt: Das Programm auf dem Bildschirm hat kein Uniform %1 (vielleicht eine Konstante im Shader), daher ändert dieses Steuerelement nichts.

%2</translation>
    </message>
</context>
<context>
    <name>lb::ScenePhrases</name>
    <message>
        <location filename="../../app/window/scene_phrases.cpp" line="+29"/>
        <source>showing normal</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws N as a colour</extracomment>
        <translation>zeigt N als Farbe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing light</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws L (towards the light) as a colour</extracomment>
        <translation>zeigt L als Farbe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing view</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws V (towards the eye) as a colour</extracomment>
        <translation>zeigt V als Farbe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing half</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws H, the half vector, as a colour</extracomment>
        <translation>zeigt H als Farbe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing reflect</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws R, the reflected light, as a colour</extracomment>
        <translation>zeigt R als Farbe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing ndotl</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws N·L as grey (&quot;ndotl&quot; is its name in files)</extracomment>
        <translation>zeigt N·L als Grauwert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing specular</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws the specular factor as grey</extracomment>
        <translation>zeigt Glanzfaktor als Grauwert</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>showing attenuation</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws a point light&apos;s attenuation as grey</extracomment>
        <translation>zeigt Abschwächung als Grauwert</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>directional light in the camera frame</source>
        <translation>gerichtetes Licht in Kamerakoordinaten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the camera frame</source>
        <translation>Punktlicht in Kamerakoordinaten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>directional light in the world frame</source>
        <translation>gerichtetes Licht in Weltkoordinaten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the world frame</source>
        <translation>Punktlicht in Weltkoordinaten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>directional light in the object frame</source>
        <translation>gerichtetes Licht in Objektkoordinaten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the object frame</source>
        <translation>Punktlicht in Objektkoordinaten</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>%n light(s) on</source>
        <translation>
            <numerusform>%n Licht an</numerusform>
            <numerusform>%n Lichter an</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the program&apos;s own light (marker hidden)</source>
        <translation>das eigene Licht des Programms (Markierung ausgeblendet)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Program: %1</source>
        <translation>Programm: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>drawn flat (per triangle)</source>
        <translation>flach gezeichnet (pro Dreieck)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 specular</source>
        <extracomment>%1 the specular model&apos;s name and cosine: &quot;Blinn-Phong (N·H)&quot;</extracomment>
        <translation>spiegelnder Anteil nach %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, %2</source>
        <extracomment>joins the status line&apos;s clauses about the program: &quot;Program: toon.vert, drawn flat&quot;</extracomment>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>perspective projection</source>
        <translation>perspektivische Projektion</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>orthographic projection</source>
        <translation>orthografische Projektion</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1  |  %2  |  %3</source>
        <extracomment>the status line&apos;s three places: the program, the light, the projection</extracomment>
        <translation>%1  |  %2  |  %3</translation>
    </message>
</context>
<context>
    <name>lb::SettingsAutosave</name>
    <message>
        <location filename="../../app/window/settings_autosave.cpp" line="+20"/>
        <source>%1 is not a settings file</source>
        <translation>%1 ist keine Einstellungsdatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 cannot be written</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Your work is saved again in %1</source>
        <translation>Ihre Arbeit wird wieder in %1 gespeichert</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Your work is not saved, trying again every %1 s: %2</source>
        <translation>Ihre Arbeit ist nicht gespeichert, neuer Versuch alle %1 s: %2</translation>
    </message>
</context>
<context>
    <name>lb::SettingsStore</name>
    <message>
        <location filename="../../app/window/settings_store.cpp" line="-24"/>
        <source>no temporary folder for the settings (%1): they are written directly</source>
        <translation>kein temporärer Ordner für die Einstellungen (%1): Diese werden direkt geschrieben</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: cannot be written</source>
        <translation>%1: kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: its scratch copy %2 cannot be written (a full temporary folder?)</source>
        <translation>%1: Die Zwischenkopie %2 kann nicht geschrieben werden (ist der temporäre Ordner voll?)</translation>
    </message>
</context>
<context>
    <name>lb::ShaderDocument</name>
    <message>
        <location filename="../../render/model/scene/shader_document.cpp" line="+204"/>
        <source>Cannot open %1</source>
        <translation>%1 kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Cannot save %1</source>
        <translation>%1 kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The shaders have no files yet: use Save As</source>
        <translation>Die Shader haben noch keine Dateien: Verwenden Sie „Shader speichern unter“</translation>
    </message>
</context>
<context>
    <name>lb::ShaderEditor</name>
    <message>
        <location filename="../../widgets/shader_editor.cpp" line="+137"/>
        <source>error: %1</source>
        <extracomment>a compiler&apos;s message under its line in the editor; %1 the message</extracomment>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
</context>
<context>
    <name>lb::ShadingPanel</name>
    <message>
        <location filename="../../widgets/shading_panel.cpp" line="+27"/>
        <source>Gouraud (per vertex)</source>
        <translation>Gouraud (pro Vertex)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Phong (per fragment)</source>
        <translation>Phong (pro Fragment)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flat (per triangle)</source>
        <translation>Flach (pro Dreieck)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gouraud: the model runs in the vertex shader and colours are interpolated; Phong: N, L, V are interpolated and the model runs for every fragment; flat: each triangle takes the colour of its last (provoking) vertex (key G: Gouraud / Phong)</source>
        <translation>Gouraud: Das Modell läuft im Vertex-Shader und die Farben werden interpoliert; Phong: N, L, V werden interpoliert und das Modell läuft für jedes Fragment; flach: Jedes Dreieck erhält die Farbe seines letzten (provozierenden) Vertex (Taste G: Gouraud / Phong)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Shading</source>
        <translation>Schattierung</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>R = reflect(-L, N), the mirrored light direction; H = normalize(L + V), the half vector (key B)</source>
        <translation>R = reflect(-L, N), die gespiegelte Lichtrichtung; H = normalize(L + V), der Halbvektor (Taste B)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <extracomment>the specular model&apos;s name and its factor: &quot;Phong: (R·V)^n&quot;</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+44"/>
        <source>Specular</source>
        <extracomment>the row of the specular term&apos;s choice (Phong or Blinn-Phong)</extracomment>
        <translation>Spiegelnd</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>Perspective: V = -posC</source>
        <translation>Perspektivisch: V = -posC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Orthographic: V = (0,0,1)</source>
        <translation>Orthografisch: V = (0,0,1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mProjection, and the view vector V that matches it (key P)</source>
        <translation>mProjection und der dazu passende Blickvektor V (Taste P)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Projection</source>
        <translation>Projektion</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Colour (lit)</source>
        <extracomment>what the surface shows: the lit colour, or a vector (N, L, V, H, R) or number as colour</extracomment>
        <translation>Farbe (beleuchtet)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>N as colour</source>
        <translation>N als Farbe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>L as colour</source>
        <translation>L als Farbe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>V as colour</source>
        <translation>V als Farbe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>H as colour</source>
        <translation>H als Farbe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R as colour</source>
        <translation>R als Farbe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>N·L as grey</source>
        <translation>N·L als Grauwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specular factor as grey</source>
        <translation>Glanzfaktor als Grauwert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Attenuation as grey</source>
        <translation>Abschwächung als Grauwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uShow: the model taken apart. Vectors as 0.5·v + 0.5 (x red, y green, z blue), numbers as grey; L, H, R and the numbers are light 1&apos;s (with several lights on too)</source>
        <translation>uShow: das Modell zerlegt. Vektoren als 0.5·v + 0.5 (x rot, y grün, z blau), Zahlen als Grauwert; L, H, R und die Zahlen gehören zu Licht 1 (auch wenn mehrere Lichter an sind)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Show</source>
        <extracomment>the row of the Show choice (what the surface shows)</extracomment>
        <translation>Anzeige</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Lighting</source>
        <extracomment>a switch: the lighting model on, or Kd unlit</extracomment>
        <translation>Beleuchtung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>uEnableLighting: off shows Kd unlit (key L)</source>
        <translation>uEnableLighting: aus zeigt Kd unbeleuchtet (Taste L)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours</source>
        <translation>Vertexfarben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Multiply ambient and diffuse by the vertex colour (vColor)</source>
        <translation>Ambienten und diffusen Anteil mit der Vertexfarbe (vColor) multiplizieren</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ambient</source>
        <translation>Ambient</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ia·Ka: uEnableAmbient (key A)</source>
        <translation>Ia·Ka: uEnableAmbient (Taste A)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse</source>
        <translation>Diffus</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Id·Kd·max(N·L, 0): uEnableDiffuse (key D)</source>
        <translation>Id·Kd·max(N·L, 0): uEnableDiffuse (Taste D)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Is·Ks·(R·V or N·H)^n: uEnableSpecular (key S)</source>
        <translation>Is·Ks·(R·V oder N·H)^n: uEnableSpecular (Taste S)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Terms</source>
        <extracomment>the row of the ambient, diffuse and specular terms&apos; switches</extracomment>
        <translation>Anteile</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Normals by the model-view (wrong)</source>
        <translation>Normalen mit der Modelview-Matrix (falsch)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transform normals by mModelView instead of its inverse transpose, to see why the normal matrix exists: under a non-uniform scale the normals tilt</source>
        <translation>Normalen mit mModelView statt mit ihrer inversen Transponierten transformieren, um zu sehen, wozu es die Normalenmatrix gibt: Bei ungleichmäßiger Skalierung kippen die Normalen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Compare&lt;/b&gt; side A with side B</source>
        <translation>&lt;b&gt;Vergleich&lt;/b&gt; von Seite A mit Seite B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Side A is the program on screen (the editor&apos;s); side B is the built-in program with the choices below, a shader pair from files, or an open exercise&apos;s reference; one camera</source>
        <translation>Seite A ist das Programm auf dem Bildschirm (das des Editors); Seite B ist das eingebaute Programm mit den Einstellungen unten, ein Shader-Paar aus Dateien oder die Referenz einer geöffneten Übung; eine gemeinsame Kamera</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Files...</source>
        <translation>Dateien...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B draws a shader pair from files (NAME.vert and NAME.frag), e.g. last week&apos;s solution</source>
        <translation>Seite B zeichnet ein Shader-Paar aus Dateien (NAME.vert und NAME.frag), z. B. die Lösung der letzten Woche</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop using these files: side B draws what it drew before them</source>
        <translation>Diese Dateien nicht mehr verwenden: Seite B zeichnet wieder, was sie vorher gezeichnet hat</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>B program</source>
        <extracomment>the program side B of the compare view draws (A and B are the two sides)</extracomment>
        <translation>B-Programm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Off</source>
        <extracomment>the compare view is off (A alone)</extracomment>
        <translation>Aus</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Side by side</source>
        <translation>Nebeneinander</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+34"/>
        <source>Wipe</source>
        <extracomment>the row of the slider that places the wipe&apos;s dividing line</extracomment>
        <translation>Wischblende</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>Difference |A - B|</source>
        <translation>Differenz |A - B|</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side by side: A left, B right; wipe: drag the line in the view; difference: |A - B| as a heat map (key C cycles)</source>
        <translation>Nebeneinander: A links, B rechts; Wischblende: die Linie in der Ansicht ziehen; Differenz: |A - B| als Heatmap (Taste C schaltet weiter)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>View</source>
        <extracomment>the compare view (off, side by side, wipe, difference); not the menu, not the camera</extracomment>
        <translation>Ansicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B: Gouraud</source>
        <extracomment>side B&apos;s shading (B is the compare view&apos;s second side)</extracomment>
        <translation>B: Gouraud</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>B: Phong</source>
        <translation>B: Phong</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>B: Flat</source>
        <translation>B: Flach</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B&apos;s shading: per vertex or per fragment</source>
        <translation>Schattierung von Seite B: pro Vertex oder pro Fragment</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>B shading</source>
        <extracomment>side B&apos;s shading (B is the compare view&apos;s second side)</extracomment>
        <translation>B-Schattierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B&apos;s specular term</source>
        <translation>Spiegelnder Anteil von Seite B</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>B: %1</source>
        <extracomment>side B&apos;s specular model (B is the compare view&apos;s second side): &quot;B: Phong (R·V)&quot;</extracomment>
        <translation>B: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>B specular</source>
        <extracomment>side B&apos;s specular term (B is the compare view&apos;s second side)</extracomment>
        <translation>B-Spiegelanteil</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Where the wipe divides A (left) from B (right)</source>
        <translation>Wo die Wischblende A (links) von B (rechts) trennt</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reset shading</source>
        <translation>Schattierung zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phong shading, Blinn-Phong specular, perspective, lighting on</source>
        <translation>Phong-Schattierung, spiegelnder Anteil nach Blinn-Phong, perspektivisch, Beleuchtung an</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the built-in program</source>
        <translation>das eingebaute Programm</translation>
    </message>
</context>
<context>
    <name>lb::Submission</name>
    <message>
        <location filename="../../app/common/submission.cpp" line="+72"/>
        <source>%1: a folder needs one NAME.vert and one NAME.frag (it has %2 and %3)</source>
        <translation>%1: Ein Ordner braucht genau eine NAME.vert und eine NAME.frag (er enthält %2 .vert und %3 .frag)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: the scene file has no program</source>
        <translation>%1: Die Szenendatei enthält kein Programm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: the scene file&apos;s program cannot be used: %2</source>
        <extracomment>%2 why the scene&apos;s program was not used (&quot;program (the vertex shader has ... characters, ...)&quot;)</extracomment>
        <translation>%1: das Programm der Szenendatei ist nicht verwendbar: %2</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: no %2 beside it (a submission is NAME.vert and NAME.frag)</source>
        <translation>%1: %2 fehlt im selben Ordner (eine Abgabe besteht aus NAME.vert und NAME.frag)</translation>
    </message>
</context>
<context>
    <name>lb::TextureControls</name>
    <message>
        <location filename="../../widgets/texture_controls.cpp" line="+28"/>
        <source>Texture</source>
        <translation>Textur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uEnableTexture: multiply ambient and diffuse by the texture (uSampler): the image file, else the mesh file&apos;s diffuse texture, else the checker</source>
        <translation>uEnableTexture: ambienten und diffusen Anteil mit der Textur (uSampler) multiplizieren: die Bilddatei, sonst die diffuse Textur der Mesh-Datei, sonst das Schachbrettmuster</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Image...</source>
        <translation>Bild...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a PNG, JPEG or any image Qt reads as this object&apos;s texture (Ctrl+T, or drop it on the window); at most %1 x %1 texels</source>
        <translation>Ein PNG, JPEG oder jedes Bild, das Qt liest, als Textur dieses Objekts öffnen (Strg+T, oder auf dem Fenster ablegen); höchstens %1 x %1 Texel</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No image: back to the mesh file&apos;s texture or the checker</source>
        <translation>Kein Bild: zurück zur Textur der Mesh-Datei oder zum Schachbrettmuster</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Repeat</source>
        <extracomment>texture wrapping: GL_REPEAT or GL_CLAMP_TO_EDGE</extracomment>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Clamp</source>
        <translation>Begrenzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Texture coordinates outside 0 to 1: the image repeats (GL_REPEAT) or its edge stretches (GL_CLAMP_TO_EDGE)</source>
        <translation>Texturkoordinaten außerhalb von 0 bis 1: Das Bild wiederholt sich (GL_REPEAT) oder sein Rand wird gestreckt (GL_CLAMP_TO_EDGE)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Nearest</source>
        <extracomment>texture filtering: GL_NEAREST or GL_LINEAR</extracomment>
        <translation>Nächster Nachbar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The texel nearest the coordinate (GL_NEAREST: blocky when magnified) or the four around it weighted (GL_LINEAR)</source>
        <translation>Das Texel, das der Koordinate am nächsten liegt (GL_NEAREST: bei Vergrößerung blockig), oder die vier umliegenden, gewichtet (GL_LINEAR)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Mipmaps</source>
        <translation>Mipmaps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where the texture is minified, read a smaller copy of it chosen by the level of detail (GL_NEAREST_MIPMAP_NEAREST, or trilinear GL_LINEAR_MIPMAP_LINEAR with the linear filter): no shimmer far away. The probe shows the level</source>
        <translation>Wo die Textur verkleinert wird, eine kleinere Kopie lesen, gewählt nach der Detailstufe (GL_NEAREST_MIPMAP_NEAREST, oder trilinear GL_LINEAR_MIPMAP_LINEAR mit dem linearen Filter): kein Flimmern in der Ferne. Die Sonde zeigt die Stufe</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (not shown)</source>
        <translation>%1 (nicht angezeigt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the checker</source>
        <translation>das Schachbrettmuster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the mesh file&apos;s texture, or the checker</source>
        <translation>die Textur der Mesh-Datei oder das Schachbrettmuster</translation>
    </message>
</context>
<context>
    <name>lb::TextureFile</name>
    <message>
        <location filename="../../render/model/scene/texture_file.cpp" line="+4"/>
        <source>%1: an empty file, not an image</source>
        <translation>%1: eine leere Datei, kein Bild</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: not an image (%2)</source>
        <translation>%1: kein Bild (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the formats read are %1</source>
        <translation>lesbare Formate sind %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 x %3 texels is more than a texture may have (%4 x %4)</source>
        <translation>%1: %2 x %3 Texel sind mehr, als eine Textur haben darf (%4 x %4)</translation>
    </message>
    <message>
        <location line="+30"/>
        <location line="+6"/>
        <source>%1: could not be read as an image: %2</source>
        <translation>%1: konnte nicht als Bild gelesen werden: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2 x %3 texels (scaled from %4 x %5)</source>
        <extracomment>%1 a file&apos;s name, %2 x %3 the texels drawn, %4 x %5 the image&apos;s own size</extracomment>
        <translation>%1: %2 x %3 Texel (skaliert von %4 x %5)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 x %3 texels</source>
        <translation>%1: %2 x %3 Texel</translation>
    </message>
</context>
<context>
    <name>lb::TrialProcess</name>
    <message>
        <location filename="../../render/trial/trial_process.cpp" line="+167"/>
        <source>compiling this program and drawing it on small frames did not finish within %1 (the trial&apos;s helper was replaced): an endless or very long loop, or a program too big for the driver?</source>
        <translation>das Kompilieren dieses Programms und das Zeichnen kleiner Testbilder wurde nicht innerhalb von %1 fertig (der Hilfsprozess für die Erprobung wurde ersetzt): eine Endlosschleife oder sehr lange Schleife, oder ein Programm, das zu groß für den Treiber ist?</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>the driver ran out of memory compiling or drawing this program (limit %1; the trial&apos;s helper was replaced)</source>
        <translation>dem Treiber ging beim Kompilieren oder Zeichnen dieses Programms der Speicher aus (Grenze %1; der Hilfsprozess für die Erprobung wurde ersetzt)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the driver crashed the trial&apos;s helper while it drew this program (it was replaced)</source>
        <translation>der Treiber hat den Hilfsprozess für die Erprobung beim Zeichnen dieses Programms abstürzen lassen (er wurde ersetzt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the trial&apos;s helper ended while it drew this program (exit code %1; it was replaced)</source>
        <translation>der Hilfsprozess für die Erprobung wurde beim Zeichnen dieses Programms beendet (Exit-Code %1; er wurde ersetzt)</translation>
    </message>
</context>
<context>
    <name>lb::UnfedInputs</name>
    <message>
        <location filename="../../render/glsl/unfed_inputs.cpp" line="+66"/>
        <source>the positions</source>
        <translation>die Positionen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the normals</source>
        <translation>die Normalen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the texture coordinates</source>
        <translation>die Texturkoordinaten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the vertex colours</source>
        <translation>die Vertex-Farben</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no array of the mesh</source>
        <translation>kein Array des Meshes</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is at location %2, where the mesh gives %3, though its name says %4 (at location %5 here): write layout(location = %5) to read them</source>
        <extracomment>%1 the input&apos;s name; %2 its location; %3 what the mesh gives there; %4 what its name says; %5 the location that has it</extracomment>
        <translation>%1 liegt an location %2, wo das Mesh %3 gibt, obwohl sein Name %4 sagt (hier an location %5): schreiben Sie layout(location = %5), um sie zu lesen</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>the scene feeds nothing to the matrix %1: it stays all zeros, and whatever it multiplies collapses to nothing on screen; bind it to one of %2 (the Bindings tab, or --bind %1=KEY)</source>
        <extracomment>%1 the uniform&apos;s name; %2 the keys it could be bound to (model-view, projection)</extracomment>
        <translation>die Szene speist nichts in die Matrix %1: sie bleibt ganz null, und was sie multipliziert, fällt auf dem Bildschirm zu nichts zusammen; binden Sie sie an eines von %2 (der Tab Bindungen oder --bind %1=KEY)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the scene feeds nothing to %1: it stays 0 unless you set it in the Uniforms panel; bind it to one of %2 (the Bindings tab, or --bind %1=KEY)</source>
        <extracomment>%1 the uniform&apos;s name; %2 the keys it could be bound to (light-position-world)</extracomment>
        <translation>die Szene speist nichts in %1: es bleibt 0, außer Sie setzen es im Uniforms-Panel; binden Sie es an eines von %2 (der Tab Bindungen oder --bind %1=KEY)</translation>
    </message>
</context>
<context>
    <name>lb::UniformPanel</name>
    <message>
        <location filename="../../widgets/uniform_panel.cpp" line="+70"/>
        <source>The program has no uniforms of its own. A uniform that no panel feeds gets a control here.</source>
        <translation>Das Programm hat keine eigenen Uniforms. Ein Uniform, das kein Bereich versorgt, erhält hier ein Steuerelement.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The program&apos;s own uniforms; values stay when you recompile.</source>
        <translation>Die eigenen Uniforms des Programms; die Werte bleiben beim Neukompilieren erhalten.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No control for: %1 (matrices, samplers and arrays).</source>
        <extracomment>%1 the names of uniforms that get no control, comma-separated</extracomment>
        <translation>Kein Steuerelement für: %1 (Matrizen, Sampler und Arrays).</translation>
    </message>
</context>
<context>
    <name>lb::UnsavedWork</name>
    <message>
        <location filename="../../app/window/unsaved_work.cpp" line="+17"/>
        <source>the shader file %1</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation>der Shader-Datei %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the shader files %1 and %2</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;; %1 and %2 are NAME.vert, NAME.frag</extracomment>
        <translation>den Shader-Dateien %1 und %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the lesson “%1”</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation>der Lektion „%1“</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the untitled scene</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation>der unbenannten Szene</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the scene “%1”</source>
        <translation>der Szene „%1“</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 and %2</source>
        <extracomment>the lesson or the scene (%1) and the shader files (%2), in &quot;Save the changes to %1&quot;</extracomment>
        <translation>%1 und %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Save the changes to %1 before closing?</source>
        <translation>Änderungen an %1 vor dem Schließen speichern?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before opening “%2”?</source>
        <translation>Änderungen an %1 vor dem Öffnen von „%2“ speichern?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before resetting everything?</source>
        <translation>Änderungen an %1 speichern, bevor alles zurückgesetzt wird?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before closing it?</source>
        <translation>Änderungen an %1 vor dem Schließen der Lektion speichern?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the changes to %1 before starting a new lesson?</source>
        <translation>Änderungen an %1 vor dem Beginn einer neuen Lektion speichern?</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Your changes will be lost if you don&apos;t save them. Save saves them all.</source>
        <translation>Ihre Änderungen gehen verloren, wenn Sie sie nicht speichern. „Speichern“ speichert alle.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Your changes will be lost if you don&apos;t save them.</source>
        <translation>Ihre Änderungen gehen verloren, wenn Sie sie nicht speichern.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
</context>
<context>
    <name>lb::ViewCoverage</name>
    <message>
        <location filename="../../render/model/measure/view_coverage.cpp" line="+86"/>
        <source>draws nothing in view: every face in view turns its back to the camera, and back faces are culled</source>
        <translation>zeichnet nichts im Bild: jede Fläche im Bild kehrt der Kamera den Rücken zu, und Rückseiten werden weggelassen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>is seen from behind: every face in view turns its back to the camera, lit as from behind (dark); Faces: Both sides lit shows that side lit</source>
        <translation>wird von hinten gesehen: jede Fläche im Bild kehrt der Kamera den Rücken zu und ist wie von hinten beleuchtet (dunkel); Flächen: Beide Seiten beleuchtet zeigt diese Seite beleuchtet</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>draws nothing in view: it lies outside the view</source>
        <translation>zeichnet nichts im Bild: es liegt außerhalb des Bildes</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>draws nothing in view: every face in view turns away from the camera and back faces are culled</source>
        <translation>zeichnet nichts im Bild: jede Fläche im Bild ist von der Kamera abgewandt, und Rückseiten werden weggelassen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>draws nothing in view: it is flat (in the %1 plane) and seen edge-on: turn it or the camera</source>
        <extracomment>%1: the plane the mesh lies in (YZ, XZ, XY)</extracomment>
        <translation>zeichnet nichts im Bild: es ist flach (in der %1-Ebene) und wird von der Kante gesehen: drehen Sie es oder die Kamera</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>draws nothing in view: it covers less than a pixel</source>
        <translation>zeichnet nichts im Bild: es bedeckt weniger als ein Pixel</translation>
    </message>
</context>
<context>
    <name>lb::Viewport</name>
    <message>
        <location filename="../../widgets/viewport.cpp" line="+33"/>
        <source>Left drag: orbit - right or middle drag: pan - wheel: zoom - R: reset view</source>
        <translation>Linke Maustaste ziehen: kreisen - rechte oder mittlere Maustaste ziehen: verschieben - Mausrad: zoomen - R: Ansicht zurücksetzen</translation>
    </message>
    <message>
        <location filename="../../render/pipeline/program_pipeline.cpp" line="+53"/>
        <source>the OpenGL context was lost while this program drew (the driver reset the GPU: an endless or very long loop?)</source>
        <translation>der OpenGL-Kontext ging verloren, während dieses Programm zeichnete (der Treiber hat die GPU zurückgesetzt: eine Endlosschleife oder sehr lange Schleife?)</translation>
    </message>
    <message>
        <location filename="../../widgets/viewport.cpp" line="+94"/>
        <source>The renderer could not start:
%1</source>
        <translation>Der Renderer konnte nicht starten:
%1</translation>
    </message>
    <message>
        <location filename="../../widgets/viewport_captions.cpp" line="+20"/>
        <source>The shader has errors (see the editor): the built-in program is drawing</source>
        <translation>Der Shader hat Fehler (siehe Editor): Das eingebaute Programm zeichnet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The shader has errors (see the editor): the last good program is drawing</source>
        <translation>Der Shader hat Fehler (siehe Editor): Das letzte funktionierende Programm zeichnet</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Refused: %1; the built-in program is drawing</source>
        <extracomment>%1 why the program was refused (a loop that never ends, a frame too slow)</extracomment>
        <translation>Abgelehnt: %1; das eingebaute Programm zeichnet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Refused: %1; the last good program is drawing</source>
        <extracomment>%1 why the program was refused</extracomment>
        <translation>Abgelehnt: %1; das letzte funktionierende Programm zeichnet</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>OpenGL %1, %2; WebGL 1 shaders run as GLSL 3.30</source>
        <extracomment>%1 the OpenGL version (4.5); %2 the driver&apos;s renderer (llvmpipe ...)</extracomment>
        <translation>OpenGL %1, %2; WebGL-1-Shader laufen als GLSL 3.30</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>OpenGL %1, %2</source>
        <extracomment>%1 the OpenGL version (4.5); %2 the driver&apos;s renderer</extracomment>
        <translation>OpenGL %1, %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>B: %1</source>
        <extracomment>side B of the compare view and the program it draws</extracomment>
        <translation>B: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the reference program</source>
        <translation>das Referenzprogramm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B: built-in %1, %2</source>
        <extracomment>side B draws the built-in program: %1 its shading, %2 its specular term</extracomment>
        <translation>B: eingebaut, %1, %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gouraud</source>
        <translation>Gouraud</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flat</source>
        <translation>flach</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phong</source>
        <translation>Phong</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A (left): %1  |  %2 (right)</source>
        <extracomment>side A (left) names its program; %2 says side B&apos;s (&quot;B: ...&quot;), on the right</extracomment>
        <translation>A (links): %1  |  %2 (rechts)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+13"/>
        <source>the program on screen</source>
        <translation>das Programm auf dem Bildschirm</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>|A - B|: not drawn yet</source>
        <translation>|A - B|: noch nicht gezeichnet</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>|A - B|, A: %7, %1: largest %2/255 at (%3, %4); %5% of the drawn pixels within %8/255; scale 0 (black) to %6/255 (white)</source>
        <translation>|A - B|, A: %7, %1: größte Differenz %2/255 bei (%3, %4); %5 % der gezeichneten Pixel innerhalb von %8/255; Skala 0 (schwarz) bis %6/255 (weiß)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (this view, %2 x %3 pixels); %4</source>
        <extracomment>%1 the difference view&apos;s figures; %2 x %3 the view&apos;s size in pixels; %4 what Check My Work measured for the case (its own frame size and figures)</extracomment>
        <translation>%1 (diese Ansicht, %2 x %3 Pixel); %4</translation>
    </message>
</context>
<context>
    <name>lb::WireReader</name>
    <message>
        <location filename="../../render/import/wire_reader.cpp" line="+50"/>
        <source>the import stream goes on after its end</source>
        <translation>der Import-Datenstrom geht nach seinem Ende weiter</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the import helper wrote something that is not a mesh stream</source>
        <translation>der Import-Helfer hat etwas geschrieben, das kein Mesh-Datenstrom ist</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the import stream holds two meshes</source>
        <translation>der Import-Datenstrom enthält zwei Meshes</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import stream announces a mesh of a bad size</source>
        <translation>der Import-Datenstrom kündigt ein Mesh mit ungültiger Größe an</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the import stream holds a record too large to be right</source>
        <translation>der Import-Datenstrom enthält einen Datensatz, der zu groß ist, um stimmen zu können</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>not enough memory for the mesh (%1 MB received)</source>
        <translation>nicht genug Speicher für das Mesh (%1 MB empfangen)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>receiving</source>
        <extracomment>a stage of loading a mesh file, shown beside its progress</extracomment>
        <translation>wird empfangen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the import stream holds an index past the last vertex</source>
        <translation>der Import-Datenstrom enthält einen Index hinter dem letzten Vertex</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the import stream holds coordinates that are not finite</source>
        <translation>der Import-Datenstrom enthält nicht endliche Koordinaten</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the import stream announces a mesh whose sizes don&apos;t add up</source>
        <translation>der Import-Datenstrom kündigt ein Mesh an, dessen Größen nicht zusammenpassen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the import stream announces a mesh of %1 MB, more than the helper may use (%2 MB)</source>
        <translation>der Import-Datenstrom kündigt ein Mesh von %1 MB an, mehr als der Helfer verwenden darf (%2 MB)</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>the import stream holds a short progress record</source>
        <translation>der Import-Datenstrom enthält einen zu kurzen Fortschritts-Datensatz</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the import failed without saying why</source>
        <translation>der Import ist ohne Angabe eines Grundes fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the import stream holds a material of the wrong size</source>
        <translation>der Import-Datenstrom enthält ein Material der falschen Größe</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the import stream holds a short texture</source>
        <translation>der Import-Datenstrom enthält eine zu kurze Textur</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the import stream holds a texture whose size doesn&apos;t add up</source>
        <translation>der Import-Datenstrom enthält eine Textur, deren Größe nicht stimmt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the import stream ended without a mesh</source>
        <translation>der Import-Datenstrom endete ohne Mesh</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the import stream holds a record of unknown type %1</source>
        <translation>der Import-Datenstrom enthält einen Datensatz unbekannten Typs %1</translation>
    </message>
</context>
<context>
    <name>lb::WorkCheck</name>
    <message>
        <location filename="../../app/common/work_check.cpp" line="+42"/>
        <source>killed by signal %1 (%2)</source>
        <extracomment>%2 is the C library&apos;s name of the signal, in English (&quot;Segmentation fault&quot;)</extracomment>
        <translation>durch Signal %1 beendet (%2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exit code %1</source>
        <translation>Exit-Code %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>no temporary folder for the check: %1</source>
        <translation>kein temporärer Ordner für die Prüfung: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>your program</source>
        <translation>Ihr Programm</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>more than %1 s</source>
        <translation>mehr als %1 s</translation>
    </message>
</context>
</TS>
