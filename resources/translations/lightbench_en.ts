<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>QFileDialog</name>
    <message>
        <location filename="../../app/common/qt_standard_words.cpp" line="+47"/>
        <source>Look in:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to the parent directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Create a New Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change to list view mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change to detail view mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sidebar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>List of places and bookmarks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recent Places</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Choose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <location line="+1"/>
        <source>Computer</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <location line="-47"/>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yes to &amp;All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;No</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N&amp;o to All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ignore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore Defaults</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QShortcut</name>
    <message>
        <location line="+4"/>
        <source>Space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Backspace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PgUp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PgDown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Del</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Print</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::BindingPanel</name>
    <message>
        <location filename="../../widgets/binding_panel.cpp" line="+24"/>
        <source>Vertex positions (location 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex normals (location 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture coordinates (location 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours (location 3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Nothing: the mesh has no array at location %1</source>
        <extracomment>%1 the location number a vertex input was linked at</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+60"/>
        <source>A vertex input is fed by its location: layout(location = N), or the slot its name gives (aPos, a_normal, inTexCoord...).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The built-in program draws: its inputs are the panels&apos;. A program of your own shows each input here with what feeds it, and you can choose what does.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n uniform(s) fed nothing: choose what feeds them; the choice is saved with the scene.</source>
        <extracomment>%n how many uniforms nothing feeds</extracomment>
        <translation>
            <numerusform>%n uniform fed nothing: choose what feeds it; the choice is saved with the scene.</numerusform>
            <numerusform>%n uniforms fed nothing: choose what feeds them; the choice is saved with the scene.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What feeds each input of the program, chosen by its name; change a choice to feed another value. The choice is saved with the scene.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>By its name: %1</source>
        <extracomment>the entry that lets the uniform&apos;s name decide what feeds it; %1 what that is</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>By its name: nothing (the name is no convention&apos;s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not fed: its own value (the Uniforms panel)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not fed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Fed with: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fed nothing: it stays 0 and decides the picture. Choose what the scene gives.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fed nothing by the scene: its own value (the Uniforms panel&apos;s control, or its initialiser).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Bindings</name>
    <message>
        <location filename="../../render/glsl/bindings.cpp" line="+26"/>
        <source>Model-view matrix (camera from object)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normal matrix (inverse transpose of model-view)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>View matrix (camera from world)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>View&apos;s normal matrix (inverse transpose of view)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position, in the Light panel&apos;s frame (x, y, z, w)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position (camera coordinates)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s ambient colour Ia</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s diffuse colour Id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s specular colour Is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s ambient colour Ka</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s diffuse colour Kd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s specular colour Ks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shininess</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s frame (0 camera, 1 world, 2 object)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light on (1) or off (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Specular model (0 Phong, 1 Blinn-Phong)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection (0 perspective, 1 parallel)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lighting on (1) or off (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours on (1) or off (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture on (1) or off (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The object&apos;s texture (unit 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation (kc, kl, kq)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s axis, in the light&apos;s frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s cut-off angle (degrees)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cosine of the spot&apos;s cut-off angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s exponent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ambient term on (1) or off (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse term on (1) or off (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Specular term on (1) or off (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show choice (0 the colour, 1 N, 2 L...)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Model matrix (world from object)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Model&apos;s normal matrix (inverse transpose of model)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection times view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection times model-view (MVP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position (world coordinates)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Direction the light shines (world)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Direction towards the light (world, unit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Camera position (world coordinates)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ia times Ka</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Id times Kd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Is times Ks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s constant factor kc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s linear factor kl</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s quadratic factor kq</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s axis (camera coordinates)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Half vector of a viewer far along +z (camera coordinates)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+126"/>
        <source>the binding %1=%2 is not used: %1 is not of the type that %2 gives (a matrix, numbers, a texture)</source>
        <extracomment>%1 the uniform&apos;s name, %2 the key chosen for it (model-view, light-diffuse)</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::BoundedRead</name>
    <message>
        <location filename="../../render/model/io/bounded_read.cpp" line="+35"/>
        <location line="+6"/>
        <source>no such file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-4"/>
        <source>a loop of symbolic links</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a symbolic link to %1, which does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 MB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 KiB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1, %2</source>
        <extracomment>a file&apos;s size limit (%1, &quot;64 MB&quot;) and where it comes from (%2, &quot;the import memory limit&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: not a regular file (a folder, a device or a pipe)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 is more than %3 may be (%4)</source>
        <extracomment>%1 a path, %2 its size, %3 a kind of file (&quot;a scene file&quot;), %4 the limit (&quot;64 MB&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: more than %2 may be (%3)</source>
        <extracomment>%1 a path, %2 a kind of file (&quot;a scene file&quot;), %3 the limit (&quot;64 MB&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: not saved: %2 would take %3, more than %4 may be (%5), so it could not be opened again</source>
        <extracomment>%1 a path, %2 what is saved (&quot;the scene&quot;), %3 its size, %4 a kind of file (&quot;a scene file&quot;), %5 the limit (&quot;64 MB&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::CaptionDialog</name>
    <message>
        <location filename="../../widgets/caption_dialog.cpp" line="+21"/>
        <source>English</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Portuguese</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>German</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+43"/>
        <source>Edit Caption</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-41"/>
        <source>What the class reads under the view. Markdown: *italic*, **bold**, `code`, lists. An empty language shows English.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (%2)</source>
        <extracomment>a caption&apos;s tab: %1 the language&apos;s name, %2 its code (en, pt, de)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>The %1 caption has %2 characters; a caption holds at most %3. Nothing was changed yet: shorten it, or Cancel.</source>
        <extracomment>%1 the language&apos;s code (en, pt, de); %2, %3 counts</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ChoiceLabels</name>
    <message>
        <location filename="../../widgets/choice_labels.cpp" line="+14"/>
        <source>camera</source>
        <comment>light frame</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>world</source>
        <comment>light frame</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>object</source>
        <comment>light frame</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>gouraud</source>
        <comment>shading</comment>
        <extracomment>Gouraud shading (per vertex), as in &quot;gouraud shading&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>phong</source>
        <comment>shading</comment>
        <extracomment>Phong shading (per fragment), as in &quot;phong shading&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>flat</source>
        <comment>shading</comment>
        <extracomment>flat shading (per triangle), as in &quot;flat shading&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>colour</source>
        <comment>show</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>normal</source>
        <comment>show</comment>
        <extracomment>the normal N, drawn as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>light</source>
        <comment>show</comment>
        <extracomment>the light vector L, drawn as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>view</source>
        <comment>show</comment>
        <extracomment>the view vector V, drawn as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>half</source>
        <comment>show</comment>
        <extracomment>the half vector H, drawn as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>reflect</source>
        <comment>show</comment>
        <extracomment>the reflected light R, drawn as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ndotl</source>
        <comment>show</comment>
        <extracomment>N·L drawn as grey</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>specular</source>
        <comment>show</comment>
        <extracomment>the specular factor drawn as grey</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>attenuation</source>
        <comment>show</comment>
        <extracomment>the attenuation drawn as grey</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/model/lighting/lighting_models.cpp" line="+29"/>
        <source>phong</source>
        <comment>specular</comment>
        <extracomment>Phong&apos;s specular term (R.V)^n, as in &quot;phong specular&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>blinn</source>
        <comment>specular</comment>
        <extracomment>Blinn-Phong&apos;s specular term (N.H)^n, as in &quot;blinn specular&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ColorEdit</name>
    <message>
        <location filename="../../widgets/color_edit.cpp" line="+21"/>
        <source>Pick %1 with the colour dialog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1, %2 channel (0 to 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Choose %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::DifferenceScaleLabels</name>
    <message>
        <location filename="../../widgets/difference_scale_labels.cpp" line="+55"/>
        <source>%1+</source>
        <extracomment>the top of the difference scale: this difference (of 255) and more</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>|A-B| of 255</source>
        <extracomment>the difference scale&apos;s title: |A-B| the difference of sides A and B, out of 255</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::EditorPanel</name>
    <message>
        <location filename="../../widgets/editor_panel.cpp" line="+41"/>
        <source>vertex</source>
        <extracomment>the shader stage a message is about, before its line:column</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>fragment</source>
        <extracomment>the shader stage a message is about, before its line:column</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>link</source>
        <extracomment>a message of the linker, about no single stage</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the scene&apos;s shaders</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>your shaders</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (edited)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+137"/>
        <source>Presets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-129"/>
        <source>Presets: the built-in programs, the slides&apos; shaders as printed, toon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Compile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compile and link now (Ctrl+Enter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Live</source>
        <extracomment>recompile while typing (a switch)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recompile after a pause in typing; off: only on Ctrl+Enter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source> ms</source>
        <extracomment>milliseconds, after the number</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The pause after the last key before a live recompile (wheel or arrow keys change it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Find (Ctrl+F)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+148"/>
        <source>Vertex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-147"/>
        <location line="+150"/>
        <source>Fragment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-144"/>
        <source>Click a message to go to its line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+125"/>
        <source>%1 is gone from the disk; your text is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 changed on disk; your unsaved edits are kept (Open it again to take the disk&apos;s version)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Vertex - %1</source>
        <extracomment>the vertex shader&apos;s tab; %1 its file&apos;s name</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fragment - %1</source>
        <extracomment>the fragment shader&apos;s tab; %1 its file&apos;s name</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Your unsaved shader edits from the last session are back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+86"/>
        <source>%1  error: %2</source>
        <extracomment>%1 where (fragment 5:3); %2 the compiler&apos;s message</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1  warning: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>linked, %n warning(s)</source>
        <translation>
            <numerusform>linked, %n warning</numerusform>
            <numerusform>linked, %n warnings</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linked</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n error(s): last good program drawing</source>
        <translation>
            <numerusform>%n error: last good program drawing</numerusform>
            <numerusform>%n errors: last good program drawing</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lb::Exercise</name>
    <message>
        <location filename="../../render/model/scene/exercise.cpp" line="+84"/>
        <source>not a number of points from 0 to %1, nor a list of one per case</source>
        <extracomment>%1 the largest number of points (&quot;1000000&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>each case&apos;s points must be a number from 0 to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 values for %2 cases (one per case)</source>
        <extracomment>%1 how many points the list gives, %2 how many cases the exercise has</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+84"/>
        <source>%1 (%2)</source>
        <extracomment>a field of an exercise as the file spells it (%1, &quot;exercise.grading.cases&quot;) and why it was not used (%2)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: not an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+38"/>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="+55"/>
        <location line="+11"/>
        <location line="+20"/>
        <source>unknown field</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-31"/>
        <source>%1: needs both a vertex and a fragment shader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+5"/>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="-51"/>
        <source>not %1</source>
        <extracomment>%1 the words a file may give, as it spells them (&quot;phong, gouraud, flat&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: no reference program (&quot;reference&quot;: {&quot;vertex&quot;: ..., &quot;fragment&quot;: ...} or {&quot;builtIn&quot;: {...}})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of range, clamped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>not [width, height] in whole pixels, 16 to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not a list of parameters; all of them vary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no such parameter &apos;%1&apos;; those are %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="+11"/>
        <source>not true or false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+17"/>
        <source>not an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>not a name of 1 to %1 characters; the mistake is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>no usable hint; the mistake is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>not a shader&apos;s text of up to 1 MiB; the mistake is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>both a program and a built-in; the mistake is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needs both a vertex and a fragment shader: the reference is the built-in program; the mistake is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>neither a program (&quot;vertex&quot;, &quot;fragment&quot;) nor &quot;builtIn&quot;: {...}; the mistake is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a built-in mistake needs a built-in reference; give the mistake as a program; the mistake is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>more than %1 mistakes; the rest are left out</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ExercisePanel</name>
    <message>
        <location filename="../../widgets/exercise_panel.cpp" line="+35"/>
        <source>light position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>point or directional</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>light frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>light colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>projection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>non-uniform scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>nothing (every case is the scene as it is)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <location line="+141"/>
        <source>Check my work</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-140"/>
        <source>Draws the exercise&apos;s cases with the program in the editor and with the reference, as the teacher&apos;s grading does, and lists each case (F9)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Out of date: the program in the editor has changed since this check. Check my work (F9) checks it as it is now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Case</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Largest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Within</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The largest difference of a channel, out of 255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Click a case to see it in the difference view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Back to my scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The scene as it was before a case was shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+43"/>
        <source>No exercise is open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An exercise is a scene file with a task, the teacher&apos;s reference program and how it is graded. File &gt; Examples &gt; &quot;Exercise: per-fragment lighting&quot; is one; File &gt; Open Scene opens others.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The share of the pixels either program draws that are within %1/255 of the reference, at %2 x %3: the difference view counts a case alike (at its own size)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Exercise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This exercise cannot be checked: its reference is missing or unusable.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference: the built-in program, %1 shading, %2 specular.</source>
        <extracomment>%1 the shading (gouraud, phong, flat); %2 the specular term (phong, blinn)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reference: the teacher&apos;s program (not shown; it is side B of the compare views, key C).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 cases at %2 x %3 pixels; a case passes when %4 of its pixels are within %5/255. The cases vary: %6.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>One frame of your program may take at most %1; a program that would take longer is refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cancel the check</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Checking: the cases are drawn with your program and the reference...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Your program does not compile:
%1</source>
        <extracomment>%1 the compiler&apos;s messages</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Your program does not compile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Your program does not link:
%1</source>
        <extracomment>%1 the linker&apos;s messages</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Your program does not link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Your program was refused:
%1</source>
        <extracomment>%1 why it was refused (a loop that never ends, a frame too slow)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Your program was refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This exercise cannot check your work: one of the known mistakes it lists cannot be drawn. Tell your teacher:
%1</source>
        <extracomment>%1 which of the exercise&apos;s known mistakes, and why (the driver&apos;s words)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The check took too long (%1) and was stopped</source>
        <extracomment>%1 how long it was given</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The check could not start:
%1</source>
        <extracomment>%1 why the checking process did not start</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The check could not start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not checked: %1:
%2</source>
        <extracomment>%1 the grading&apos;s status word (English, as the report has it); %2 its reason</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Passed: all %1 cases (in each, at least %2 of the pixels within %3/255); largest difference %4/255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Not yet: %1 of %2 cases pass; largest difference %3/255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Click a case to see it in the difference view.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (as given)</source>
        <extracomment>case 0 of the list: the exercise&apos;s scene as it is, not varied</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>passed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nothing drawn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Largest difference at (%1, %2) of the %3 x %4 frame; %5 pixels drawn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 pixels drawn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Your failing cases match the exercise&apos;s known mistake &quot;%1&quot; in %2 of their pixels, far more than they match the reference</source>
        <extracomment>%1 the mistake&apos;s name as the exercise gives it (data, English); %2 a share (&quot;98.5%&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Check My Work, at %1 x %2: largest %3/255, %4 within %5/255</source>
        <extracomment>the difference view&apos;s caption for a case of the list; %1 x %2 the check&apos;s frame</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Check My Work, at %1 x %2: nothing drawn</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ExportSizeDialog</name>
    <message>
        <location filename="../../widgets/export_size_dialog.cpp" line="+12"/>
        <source>Export Image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source> px</source>
        <extracomment>pixels, after the number</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The view is drawn again at this size, not scaled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose File...</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::FileArguments</name>
    <message>
        <location filename="../../app/window/file_arguments.cpp" line="+52"/>
        <source>Files not opened</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lightbench opens one scene or lesson at a time, the first file given (%1); the files below were not opened. Open them with File &gt; Open Scene or File &gt; Open Lesson.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::FileLimit</name>
    <message>
        <location filename="../../app/window/settings_store.cpp" line="+32"/>
        <location line="+20"/>
        <source>a settings file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/import/import_process.cpp" line="+55"/>
        <source>a texture file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+129"/>
        <source>a mesh file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the import memory limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/model/scene/lesson.cpp" line="+208"/>
        <location line="+42"/>
        <source>a lesson file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <source>the lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/model/scene/scene_file.cpp" line="+186"/>
        <location line="+15"/>
        <source>a scene file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <source>the scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/model/scene/shader_document.cpp" line="+21"/>
        <source>a shader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/model/scene/texture_file.cpp" line="+31"/>
        <source>an image</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::FrameLook</name>
    <message>
        <location filename="../../render/model/measure/frame_look.cpp" line="+50"/>
        <source>your program draws nothing: every pixel of the frame is the background (the object is outside the view, or a matrix fed nothing collapses it; the Bindings tab shows what feeds each input)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>your program draws the object all black: if it is not meant to be, a light or colour input it reads may be fed nothing (the Bindings tab shows what feeds each input)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Grading</name>
    <message>
        <location filename="../../render/model/grading/grading.cpp" line="+136"/>
        <source>passed</source>
        <extracomment>the outcome of a case, at the end of a grading sheet&apos;s title</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 - case %2: largest difference %3/255, %4% of %5 pixels within tolerance, %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 - case %2: largest difference %3/255 at (%4, %5), %6% of %7 pixels within tolerance, %8</source>
        <extracomment>%4, %5: the pixel that differs most</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>student</source>
        <extracomment>the captions under a grading sheet&apos;s three frames</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>|student - reference| (white: 64/255)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Help</name>
    <message>
        <location filename="../../app/window/help.cpp" line="+52"/>
        <source>%1, %2</source>
        <extracomment>shortcuts that do the same: all but the last two, &quot;Ctrl++, Ctrl+= or ...&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 or %2</source>
        <extracomment>shortcuts that do the same: &quot;F11 or F5&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Menus</source>
        <extracomment>Help &gt; Keyboard Shortcuts: the heading over every menu&apos;s keys</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Shader editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>compile and link now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>find in the shader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>undo / redo (also what a preset, an example or a reset replaced)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>complete the word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>delete / duplicate the line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>View</source>
        <extracomment>Help &gt; Keyboard Shortcuts: the heading over the mouse and keys of the 3D view (not the View menu)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>left drag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>orbit the camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>click</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>select the object under the cursor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>right or middle drag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>pan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>zoom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+click, Shift+click</source>
        <extracomment>the keys as the keyboard names them (Ctrl, Shift), held while clicking</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>probe the surface point (drag to move it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drag the wipe&apos;s line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>move the wipe (compare)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>drop a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>open a mesh, a scene, a lesson or a shader pair</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Keyboard shortcuts - lightbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Features - lightbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The README is missing from this build.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>About lightbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;lightbench %1&lt;/h3&gt;&lt;p&gt;A workbench for the lighting model of computer graphics courses: ambient, diffuse and specular terms, Phong and Blinn-Phong, Gouraud and Phong shading, every pixel checked against a CPU reference.&lt;/p&gt;&lt;p&gt;Qt %2 (built with %3)&lt;br&gt;%4&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>OpenGL not started yet</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ImageTruncation</name>
    <message>
        <location filename="../../render/model/io/image_truncation.cpp" line="+33"/>
        <source>no image data (no scan)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file ends inside the image data (no end-of-image marker): cut short?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the file ends inside its header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the file ends inside the image data (%1 of %2 bytes): cut short?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ImportProcess</name>
    <message>
        <location filename="../../render/import/import_process.cpp" line="-156"/>
        <source>the importer crashed with a segmentation fault while reading this file; the workbench is fine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the importer crashed with an abort while reading this file; the workbench is fine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with a bus error while reading this file; the workbench is fine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with an arithmetic error while reading this file; the workbench is fine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the importer crashed with an illegal instruction while reading this file; the workbench is fine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with signal %1 (%2) while reading this file; the workbench is fine</source>
        <extracomment>%1 a signal&apos;s number, %2 the system&apos;s name for it</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>texture &apos;%1&apos;: outside the mesh&apos;s folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>texture &apos;%1&apos; not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1: cannot start the import helper &apos;%2&apos;: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1: not readable (permissions)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the file is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1: cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: gave up after %2 s (the import time limit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>gave up after %1 s of CPU time (the import time limit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import helper was killed (by the system, for memory?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of memory: reading this file needs more than the import memory limit (%1 MB)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the import helper stopped (exit code %1) before sending the whole mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import helper stopped (exit code %1) before sending the whole mesh: %2</source>
        <extracomment>%2 the last line the helper wrote on its error output (its own words, in English)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+41"/>
        <source>embedded texture unreadable: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>texture %1</source>
        <extracomment>%1 why a texture file cannot be used, &quot;PATH: reason&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>texture &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file has a texture but no texture coordinates</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Language</name>
    <message>
        <location filename="../../app/common/language.cpp" line="+48"/>
        <source>&amp;System</source>
        <extracomment>View &gt; Language: follow the system&apos;s language (LANG)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/language_menu.cpp" line="+21"/>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../../app/window/run_window.cpp" line="+142"/>
        <source>Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The window changes its language when lightbench starts again. Restart now?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lightbench closes as it does on Quit, asking about unsaved work, and opens again where you were.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Restart &amp;Now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Later</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/run_window.cpp" line="+1"/>
        <source>lightbench could not start again. Start it yourself to see the new language.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Lesson</name>
    <message>
        <location filename="../../render/model/scene/lesson.cpp" line="-218"/>
        <source>%1 (%2)</source>
        <extracomment>a field of a lesson file (%1, &quot;step 2: caption.de&quot;) and why it was not used (%2)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&quot;%1&quot; is not one of %2</source>
        <extracomment>%1 a word the file gave, %2 the words allowed (as files spell them)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a value that is not text is not one of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+32"/>
        <source>%1: the scene file %2 (%3) is past what is left of the lesson&apos;s limit (%4 for the lesson and its scene files)</source>
        <extracomment>%1 the step (&quot;step 3&quot;), %2 a path, %3 its size, %4 the limit</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: no scene (&quot;scene&quot; must be a scene object or the name of a scene file)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+45"/>
        <source>%1: not a lesson file: %2 at byte %3</source>
        <extracomment>%1 a path, %2 Qt&apos;s JSON parser&apos;s reason</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: a scene file, not a lesson (open it with File &gt; Open Scene)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: not a lesson file (&quot;format&quot; is not &quot;%2&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>missing or not a number; read as %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>newer than this lightbench&apos;s %1: what it does not know is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the lesson has no steps (&quot;steps&quot; must be a list of steps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 steps; a lesson may have at most %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>step %1</source>
        <extracomment>where in a lesson file a message is about: &quot;step 3: title (not text)&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: not an object</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::LessonActions</name>
    <message>
        <location filename="../../app/window/lesson_actions.cpp" line="+43"/>
        <source>Open Recent &amp;Lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The last lesson could not be opened again: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Open &amp;Lesson...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lesso&amp;ns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>(none built in)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Less&amp;on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Next Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Previous Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;First Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Last Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New Lesson from This &amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Add This View as a Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace the Step with &amp;This View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rena&amp;me Step...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit &amp;Caption...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move Step &amp;Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move Step &amp;Down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remo&amp;ve Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save Lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Lesson &amp;As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Close Lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Caption &amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Same as the Window</source>
        <extracomment>Lesson &gt; Caption Language: the same language as the window&apos;s menus (View &gt; Language)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+54"/>
        <source>untitled lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The lesson could not be opened; nothing changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+22"/>
        <source>%1 opened; %n step(s) cannot be shown (the lesson bar says why there).</source>
        <translation>
            <numerusform>%1 opened; %n step cannot be shown (the lesson bar says why there).</numerusform>
            <numerusform>%1 opened; %n steps cannot be shown (the lesson bar says why there).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%1 opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>%1 opened; %n field could not be used and kept their defaults.</numerusform>
            <numerusform>%1 opened; %n fields could not be used and kept their defaults.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+115"/>
        <location filename="../../app/window/lesson_authoring.cpp" line="+35"/>
        <location line="+34"/>
        <source>Step %1</source>
        <extracomment>a new step&apos;s title, until the teacher renames it (saved in the lesson file)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Open a lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lessons (*.lblesson *.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <location filename="../../app/window/lesson_authoring.cpp" line="-37"/>
        <source>Lesson</source>
        <extracomment>a new lesson&apos;s title, until the teacher renames it (saved in the lesson file)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/lesson_authoring.cpp" line="+26"/>
        <source>A lesson has at most %1 steps and this one has them all: the view was not added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+40"/>
        <source>The step keeps its title.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A step&apos;s title cannot be empty.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The title has %1 characters; a title holds at most %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The step keeps its caption.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 caption has %2 characters; a caption holds at most %3.</source>
        <extracomment>%1: the caption&apos;s language code (en, de, pt)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>The step stays.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A lesson keeps at least one step; Close Lesson puts it away.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>The lesson was not saved; it stays open with its changes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved the lesson to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Lessons (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lightbench lessons (*.lblesson)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Rename Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The title of step %1:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::LessonBar</name>
    <message>
        <location filename="../../widgets/lesson_bar.cpp" line="+44"/>
        <source>The previous step (PageUp, Left)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The next step (PageDown, Right, Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reset Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This step as the lesson has it: your changes to it are set aside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The Lesson menu: add, rename, caption, move and save steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Close the lesson (the scene stays)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Step %1 of %2</source>
        <extracomment>where the class is in the lesson: step %1 of %2 steps</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>This step cannot be shown; the scene is as it was. %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+65"/>
        <source>[picture]</source>
        <extracomment>in a lesson&apos;s caption, where the markdown had an image (never shown there)</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::LightPanel</name>
    <message>
        <location filename="../../widgets/light_panel.cpp" line="+40"/>
        <location line="+172"/>
        <source>Light %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-169"/>
        <source>Up to four lights; their terms add up. A shader that declares one light (not an array) reads light 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>On</source>
        <extracomment>the light is switched on (a check box)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uLightEnabled[i]: a light switched off adds nothing (its colours go to shaders as black)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Light</source>
        <extracomment>the row of the light&apos;s on/off switch</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>w = 1: point light</source>
        <extracomment>w is the light position&apos;s 4th (homogeneous) coordinate: a symbol, not a word</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>w = 0: directional</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lightPosition.w: 1 puts the light at (x, y, z); 0 makes (x, y, z) the direction towards a light at infinity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Type</source>
        <extracomment>a light&apos;s type: point or directional</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Camera: moves with the eye</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>World: fixed in the scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Object: turns with the model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame lightPosition is given in. Camera: used as is (variant I); world: mView / mViewNormals (II); object: mModelView / mNormals (III)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The object whose frame an object-frame light is given in: the light turns and moves with it, and lights every object from there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Frame</source>
        <extracomment>the coordinate frame the light&apos;s position is given in</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Of object</source>
        <extracomment>the object whose frame an object-frame light is given in</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Atten. kc kl kq</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Spot axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Spot cutoff, exp</source>
        <extracomment>the spotlight&apos;s cutoff angle and exponent</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This light&apos;s defaults; light 1&apos;s are the slides&apos; (0, 1.8, 1.3, 1) in world coordinates</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::LightingParameters</name>
    <message>
        <location filename="../../render/model/lighting/lighting_parameters.cpp" line="+16"/>
        <source>w must be 0 (directional) or 1 (point)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a directional light (w = 0) with the direction 0, 0, 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>kc, kl and kq all 0 (the light would be infinite)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a direction of length 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>lightPosition.%1: the light&apos;s %1 in the chosen frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 (%2): the light&apos;s ambient intensity</source>
        <extracomment>%1 the symbol (Ia, Id, Is); %2 the uniforms that carry it</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (%2): the light&apos;s diffuse intensity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (%2): the light&apos;s specular intensity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>lightAttenuation.%1 (%2): a point light&apos;s terms are divided by kc + kl·d + kq·d², d its distance to the surface (1, 0, 0: none; a directional light is never attenuated)</source>
        <extracomment>%1 the axis (x, y, z); %2 its name (kc, kl, kq)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>spotDirection.%1: the spotlight&apos;s axis, from the light, in the light&apos;s frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>spotCutoff: the cone&apos;s half-angle; outside it the light adds nothing, ambient included (180: no spot)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>spotExponent: inside the cone the terms are scaled by max(-L·D, 0)^exponent, brighter towards the axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (%2): the material&apos;s ambient reflection coefficients</source>
        <extracomment>%1 the symbol (Ka, Kd, Ks); %2 the uniforms that carry it</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 (%2): the material&apos;s diffuse reflection coefficients</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 (%2): the material&apos;s specular reflection coefficients</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>shininess: the specular exponent n in (R.V)^n or (N.H)^n; higher gives a smaller, sharper highlight</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::LoadProgress</name>
    <message>
        <location filename="../../widgets/load_progress.cpp" line="+21"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop loading: the import helper is stopped, the current mesh stays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Loading %1...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Loading %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::LocalizedText</name>
    <message>
        <location filename="../../render/model/scene/localized_text.cpp" line="+29"/>
        <source>not text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 characters; at most %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a language code</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Loops</name>
    <message>
        <location filename="../../render/glsl/loop_messages.cpp" line="+18"/>
        <source>this loop runs %1 times for every fragment: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this loop runs %1 times for every fragment (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this loop runs %1 times for every vertex: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this loop runs %1 times for every vertex (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every fragment: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every fragment (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every vertex: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every vertex (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>this loop never ends: it has no condition and nothing in it breaks, returns or discards (the driver may drop it and draw garbage, or hang)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this loop never ends: its condition is always true and nothing in it breaks, returns or discards (the driver may drop it and draw garbage, or hang)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this program never finishes a frame: the loop here has no condition (or an always-true one) and no break, return or discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>this loop never ends once it starts: its condition reads %1, and nothing in the loop changes it</source>
        <extracomment>%1 the names the loop&apos;s condition reads, as the shader spells them (&quot;i, n&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this loop never ends once it starts: its condition reads %1, and nothing in the loop changes them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 (the loop comes from macro %2, used on this line)</source>
        <extracomment>%1 a message about a loop, %2 the name of the macro that writes the loop</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::MacroExpansion</name>
    <message>
        <location filename="../../render/glsl/macro_expansion.cpp" line="+94"/>
        <source>macro %1 expands through more than %2 macros, one inside another: refused before the driver sees it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>macro %1 expands to more than a million tokens (a macro that doubles itself?): refused before the driver sees it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>macro %1 expands to more than 1 MB of text (a macro that doubles itself?): refused before the driver sees it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+111"/>
        <source>macro %1 calls macros inside macro arguments more than %2 deep: refused before the driver sees it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::MainWindow</name>
    <message>
        <location filename="../../app/window/main_window.cpp" line="+85"/>
        <source>Light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Uniforms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bindings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Probe</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Plots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exercise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Shader editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+40"/>
        <location filename="../../app/window/main_window_menus.cpp" line="+53"/>
        <location filename="../../app/window/main_window_unsaved.cpp" line="+92"/>
        <location line="+13"/>
        <source>Shader files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Unsaved shader edits from the last session are back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Everything reset; Ctrl+Z in the editor brings your shader text back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Everything reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The program on screen computes V = (0,0,1), the parallel view vector, under the perspective projection; the reference uses V = -P, so the two differ away from the middle of the view. The orthographic projection (key P) makes them agree.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 shades as it is written: Gouraud/Phong does not change it. A preset or Reset Everything brings the built-in program, which follows this choice.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The program in the editor (%1) shades Gouraud (per vertex) whatever this says. Load a preset or Reset Everything to switch shading.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The program in the editor (%1) shades Phong (per fragment) whatever this says. Load a preset or Reset Everything to switch shading.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1, step %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1[*] - lightbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_budget.cpp" line="+44"/>
        <source>More would take more memory than the scene&apos;s meshes may take on this machine: %1 for all objects together.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_exercise.cpp" line="+30"/>
        <source>Side B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not checked: does not compile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: does not link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: timed out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: could not start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: crashed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: unreadable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+2"/>
        <source>Not checked: the exercise has a broken mistake</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not checked: %1</source>
        <extracomment>a check that graded nothing, for a reason this version does not know (%1, in English)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Check cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Checked: %1 of %2 cases pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+53"/>
        <location line="+16"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>the exercise&apos;s reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-17"/>
        <source>the exercise&apos;s reference (built-in)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+39"/>
        <source>the built-in program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-35"/>
        <source>side B (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Side B draws %1: it shades as it is written, so these choices do nothing. The x button brings back %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Side B draws the exercise&apos;s reference program: it shades as it is written, so these choices do nothing.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the exercise&apos;s reference (built-in, %1 shading, %2 specular)</source>
        <extracomment>%1: gouraud, phong or flat; %2: phong or blinn</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the built-in program, %1 shading and %2 specular (the exercise&apos;s reference)</source>
        <extracomment>%1: gouraud, phong or flat; %2: phong or blinn</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The exercise&apos;s reference fixes side B&apos;s choices.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Side B is unchanged: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Side B is unchanged: %1 does not build:
%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Side B: a shader pair (NAME.vert or NAME.frag) or a scene file&apos;s program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shader pairs and scene files (*.vert *.frag *.json *.lbscene);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The check could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Case %1 in the difference view (key C: the other compare views; &quot;Back to my scene&quot; in the Exercise panel)</source>
        <extracomment>&quot;Back to my scene&quot; is the Exercise panel&apos;s button: its name as translated there</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_menus.cpp" line="-13"/>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Chec&amp;k My Work</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>F9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Side B: Shader Files...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../../app/window/main_window_unsaved.cpp" line="-5"/>
        <source>Shader pairs (*.vert *.frag);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open S&amp;haders...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+O</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a shader pair (NAME.vert and NAME.frag)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save Shaders</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Alt+S</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Shaders As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <extracomment>the menu (camera, probe, zoom, presentation, docks), not the 3D view itself</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reset &amp;Everything</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Undo in the Editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Redo in the Editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <source>Ctrl+Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Find in the Shader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Toggle &amp;Gouraud / Phong</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>G</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Toggle Phong / &amp;Blinn-Phong specular</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The program in the editor (%1) computes its own specular term: load a preset or Reset Everything to switch it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Toggle &amp;Perspective / Orthographic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>P</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Toggle &amp;Lighting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>L</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Toggle the &amp;Ambient Term</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toggle the &amp;Diffuse Term</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toggle the &amp;Specular Term</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>D</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Compare: Off / Side by Side / Wipe / Difference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Reset Camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clear the &amp;Probe (in Presentation Mode: Leave It)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Esc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Auto-rotate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Features (README)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About lightbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Zoom &amp;In Editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+=</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom &amp;Out Editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reset Editor &amp;Zoom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>UI &amp;Scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1%</source>
        <extracomment>View &gt; UI Scale: a size in percent (&quot;125%&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Fit the &amp;Window to the Screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_presentation.cpp" line="+54"/>
        <source>&amp;Presentation Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>F11</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>F5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Shift+F5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Full screen, the presentation UI scale, the view large (F6: the panels)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the Panels in Presentation &amp;Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>F6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Blank the Screen (Presentation Mode)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Faded Probe Arrows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The probe&apos;s arrows thin and see-through, so the highlight under them stays visible</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>B or . blanks the screen in presentation mode (F5 or F11); Phong / Blinn-Phong is Ctrl+B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Presentation mode (F5) will show the panels (F6 hides them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Presentation mode (F5) will hide the panels (F6 shows them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The editor needs %1 px at this scale: View &gt; Shader editor shows it</source>
        <extracomment>View &gt; Shader editor: the menu&apos;s and the dock&apos;s names as translated there</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_unsaved.cpp" line="-1"/>
        <source>Save the shader pair as NAME.vert and NAME.frag</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::MaterialPanel</name>
    <message>
        <location filename="../../widgets/material_panel.cpp" line="+68"/>
        <source>Shininess</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The selected object&apos;s material back to the slides&apos; red plastic: Ka = Kd = (1, 0, 0), Ks = (1, 1, 1), n = 6</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::MeshActions</name>
    <message>
        <location filename="../../app/window/mesh_actions.cpp" line="+68"/>
        <source>Open &amp;Recent Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Texture not used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>An image could not be used as a texture.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Mesh not built</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An object&apos;s mesh could not be built; it keeps what it drew before.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Open &amp;Mesh...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+M</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open &amp;Texture Image...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+T</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Preferences...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ctrl+,</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;Normals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>N</source>
        <comment>shortcut</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 not loaded (%2 drawn)</source>
        <extracomment>%1: the mesh file; %2: the built-in shape drawn instead (cube, sphere, ...)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 triangles, %3 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+4"/>
        <location line="+11"/>
        <source>%1; %2</source>
        <extracomment>a mesh&apos;s short summary (%1) and what was turned in it or why it draws nothing (%2: &quot;faces turned: ...&quot;, &quot;draws nothing in view: ...&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-6"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Meshes Assimp reads (%1);;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open a mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Open an image as the selected object&apos;s texture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Images (%1);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Mesh not loaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A mesh file the scene names could not be loaded. Its objects draw their shapes and keep its name, so saving keeps it; it is read again after the file changes (at your next change to the scene) or when you open it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The mesh could not be loaded; the previous one stays.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Files not used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Some files could not be used.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::MeshFile</name>
    <message>
        <location filename="../../render/model/mesh/mesh_file.cpp" line="+41"/>
        <source>%1 points, lines or broken faces skipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 vertices with non-finite coordinates dropped, with the %2 triangles using them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 normals with non-finite coordinates: the file&apos;s normals not used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: %2 vertices, %3 triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s, normals generated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s, normals generated (the file has none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (%2)</source>
        <extracomment>a mesh&apos;s summary (%1) and what was skipped or not used in its file (%2, a list)</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::MeshOrientation</name>
    <message>
        <location filename="../../render/model/mesh/mesh_orientation.cpp" line="+246"/>
        <source>faces turned: the file winds them clockwise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>faces of %1 of %2 closed parts turned: the file winds them clockwise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>normals turned: the file&apos;s point inwards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>normals of %1 of %2 closed parts turned: the file&apos;s point inwards</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::MessageText</name>
    <message>
        <location filename="../../render/model/io/message_text.cpp" line="+85"/>
        <source>... and %1 more</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::NumberBox</name>
    <message>
        <location filename="../../widgets/number_box.cpp" line="+68"/>
        <source>Not a number: digits, a sign in front and one decimal separator.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A whole number, typed without separators.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One decimal separator, a point or a comma (2.5 or 2,5), and no thousands separators.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This box takes whole numbers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>This box takes %n decimal(s).</source>
        <translation>
            <numerusform>This box takes %n decimal.</numerusform>
            <numerusform>This box takes %n decimals.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This box takes %1 to %2.</source>
        <extracomment>%1 the lowest number the box takes, %2 the highest (with their units)</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ObjectLoader</name>
    <message>
        <location filename="../../app/window/mesh_actions.cpp" line="-25"/>
        <location filename="../../render/import/object_loader.cpp" line="+230"/>
        <location line="+186"/>
        <source>Loading cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/import/object_loader_textures.cpp" line="+67"/>
        <source>%1 (the objects naming it show the mesh file&apos;s texture or the checker, and keep its name for when the file is back)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/import/object_loader.cpp" line="-243"/>
        <source>%1: not used: its object was removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+53"/>
        <source>%1: not loaded: cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: not loaded: its object was removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+126"/>
        <source>building</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ObjectMesh</name>
    <message>
        <location filename="../../render/model/mesh/object_mesh.cpp" line="+34"/>
        <source>out of memory building %1&apos;s normals (%2 triangles)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of memory building the cube</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>out of memory building the sphere at tessellation %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>out of memory building the torus at tessellation %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>out of memory building the plane at tessellation %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+103"/>
        <source>out of memory building a mesh</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ObjectPanel</name>
    <message>
        <location filename="../../widgets/object_panel.cpp" line="+31"/>
        <source>The scene&apos;s objects, each with its own mesh, transform and material: select one to edit it here and in the Material panel (or click it in the view). Untick to hide; double-click to rename</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new sphere in the first free place near the centre (at most %1 objects; R frames them all)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Duplicate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A copy of the selected object, material and all, in the first free place near the centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Removes the selected object (the last one stays); lights in its frame go to the object before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cube (flat faces)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Sphere (smooth)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Torus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The object: vPosition and vNormal come from this mesh. A built-in shape replaces a mesh file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Open...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a mesh file: any format Assimp reads (Ctrl+M; or drop a file on the window)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Subdivisions of the sphere, torus and plane. Few vertices show Gouraud&apos;s weakness: its highlight follows the vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Tessellation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From the mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Smooth (crease angle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vNormal: the mesh&apos;s own normals (generated smooth when a file has none), or generated: smooth, averaged over the triangles around a vertex within the crease angle, or flat, one per triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Normals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>As in the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Both sides lit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which way a mesh file&apos;s faces look. Outward: a closed part wound inwards (lit from inside) is turned, with its normals, and the status line says so; as in the file; every face flipped; or both sides lit, each with the normal facing the camera (for open meshes: a sheet, a scan with holes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Generated smooth normals average only triangles that meet at less than this angle: 0 is flat, 180 smooths every edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Crease angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show normals as lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A short line along each vertex normal, transformed by mNormals as the shaders do (key N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cull back faces (closed meshes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Triangles facing away from the camera are not drawn: the same picture for a closed mesh, about twice as fast; an open mesh shows holes where its inside was</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Use the mesh file&apos;s material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The mesh file&apos;s ambient, diffuse and specular colours and shininess replace Ka, Kd, Ks and shininess: now, and whenever a file is loaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Rotation about %1 in degrees (model matrix; applied X, then Y, then Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Scale along %1. A non-uniform scale is why normals need mNormals, the inverse transpose of mModelView</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Translation along world %1: where the object&apos;s centre lies (model matrix, applied last)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Rotate</source>
        <extracomment>the row of the object&apos;s rotation about X, Y and Z</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scale</source>
        <extracomment>the row of the object&apos;s scale along X, Y and Z</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move</source>
        <extracomment>the row of the object&apos;s translation along X, Y and Z</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Auto-rotate about Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turns the model: a light in the object frame turns with it (key Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reset object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The selected object back to the coarse unit sphere, unrotated, unscaled and not turning; its name, place and material stay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+65"/>
        <source>File: %1</source>
        <extracomment>the shape combo&apos;s entry for a mesh file; %1 the file&apos;s name</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File: %1 (not loaded)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Offscreen</name>
    <message>
        <location filename="../../render/gl/offscreen.cpp" line="+49"/>
        <source>cannot create an OpenGL context (is there an X server with OpenGL?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cannot make the OpenGL context current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>OpenGL 3.3 is needed, the driver gives %1.%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>cannot create a %1x%2 framebuffer</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::PlotChart</name>
    <message>
        <location filename="../../widgets/plot_chart.cpp" line="+175"/>
        <source>Angle between R and V (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle between N and L (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance d from the light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle from the spot&apos;s axis (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specular factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Specular factor&lt;br&gt;&lt;small&gt;Phong (R·V)^n, Blinn-Phong (N·H)^n; dashed: Blinn-Phong at 4n&lt;/small&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Diffuse factor&lt;br&gt;&lt;small&gt;against the angle of incidence&lt;/small&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Attenuation&lt;br&gt;&lt;small&gt;against the distance from the light&lt;/small&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Spotlight factor&lt;br&gt;&lt;small&gt;against the angle from its axis&lt;/small&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The three terms as V sweeps&lt;br&gt;&lt;small&gt;the plane of incidence, N up; radius: the mean of red, green and blue&lt;/small&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>No point light is on: a directional light (w = 0) is not attenuated.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No spotlight: every light that is on has a cutoff of 180°. Set a cutoff in the Light panel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No light is on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No lobe: the light is at the surface&apos;s point, where L has no direction. Move the light off the surface.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Ambient</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Specular</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::PlotsPanel</name>
    <message>
        <location filename="../../widgets/plots_panel.cpp" line="+42"/>
        <source>Specular: Phong and Blinn-Phong</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diffuse: max(N·L, 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attenuation with distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spotlight falloff</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lobe at the probed point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which of the model&apos;s curves to draw</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write this plot as a PNG or SVG picture, or its samples as CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+100"/>
        <source>No point probed: light %1&apos;s lobe where N faces the camera at the selected object&apos;s centre. Ctrl+click the surface to plot it at a point.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Ctrl+click the surface: the probed point&apos;s own values appear as dots.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light %1&apos;s terms at the probed point. The dots are where V&apos;s part in the plane of incidence points; the Probe tab has the values at V itself.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No dot: at the probed point every light is behind the surface (N·L &lt; 0) or outside the plot.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Dots: each light&apos;s angle at the probed point (for Blinn-Phong, 2·acos(N·H)).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>PNG images (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SVG pictures (*.svg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV samples (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+15"/>
        <source>Export the plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The plot could not be written; nothing was changed.
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported the plot to %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::PreferencesDialog</name>
    <message>
        <location filename="../../widgets/preferences_dialog.cpp" line="+15"/>
        <source>Preferences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mesh files are read by a helper process (lightbench-import). When it needs more memory or time than this, it is stopped and the file gets a message; the workbench carries on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source> MB</source>
        <extracomment>megabytes, after the number</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The helper&apos;s address-space limit. Default: half of this machine&apos;s memory (%1 MB). Also --import-memory-limit MB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Import memory limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+9"/>
        <source> s</source>
        <extracomment>seconds, after the number</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-7"/>
        <source>A load that takes longer is stopped. Default: %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import time limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Your shader program is tried on tiny frames before it draws; when one frame at the view&apos;s size would take longer than this, it is refused and the last good program keeps drawing. Default: %1 s. Also --frame-budget SECONDS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Frame budget</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move the camera and the lights smoothly between a lesson&apos;s steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>So the class sees where they go; off: each step jumps</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Presets</name>
    <message>
        <location filename="../../render/glsl/presets.cpp" line="+37"/>
        <source>Built-in: Phong shading (per fragment)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Built-in: Gouraud shading (per vertex)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Slides: Gouraud, WebGL 1 as printed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Slides: Phong shading, WebGL 1 as printed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Toon (the exercise&apos;s &quot;like Zelda&quot;), GLSL 3.30</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ProbeEquation</name>
    <message>
        <location filename="../../render/model/measure/probe_equation.cpp" line="+150"/>
        <source>Lighting is off: the surface shows Kd times the base colour instead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Flat shading draws the model at the triangle&apos;s last (provoking) vertex, one colour for the triangle; these numbers are the model at this point.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Gouraud shading draws the model at the triangle&apos;s vertices, interpolated; these numbers are the model at this point.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-72"/>
        <source>(base multiplies ambient and diffuse only)</source>
        <extracomment>after the equation in symbols, where a texture&apos;s base colour multiplies it</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>(0: the light is behind the surface)</source>
        <extracomment>after the specular term&apos;s numbers, where N·L &lt; 0</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-5"/>
        <source>[off]</source>
        <extracomment>before a term the Shading panel switched off</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-7"/>
        <source>light %1: %2</source>
        <extracomment>a light&apos;s line of the equation: %1 its number, %2 its factors (att·spot = ...)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+41"/>
        <source>pixel = %1 of 255 (clamped to 0..1)</source>
        <extracomment>%1 the pixel&apos;s red, green and blue, as (r, g, b)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The surface shows %1, not this colour.</source>
        <extracomment>%1 what the Shading panel&apos;s Show choice draws instead (normal, ndotl, ...)</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ProbePanel</name>
    <message>
        <location filename="../../widgets/probe_panel.cpp" line="+68"/>
        <source>Copy the Equation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The lighting equation with this point&apos;s numbers, as text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Ctrl+click (or Shift+click) the surface to probe a point: the vectors, N·L, the specular angle and the three terms, beside the pixel the GPU drew. Esc clears it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>No surface at (%1, %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+107"/>
        <source>pixel (%1, %2), %3, triangle %4</source>
        <extracomment>%1, %2 the pixel; %3 the object&apos;s name; %4 the triangle&apos;s number</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pixel (%1, %2), %3, triangle %4, side B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pixel (%1, %2), %3, triangle %4, side A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>P (eye)</source>
        <extracomment>P, the probed point, in eye coordinates</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>levels %1 and %2 (%3% of %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>level %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>uv (%1, %2), level of detail %3: %4, mipmaps</source>
        <extracomment>%1, %2 the texture coordinates; %3 the level of detail; %4 the mipmap levels read</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uv (%1, %2), level of detail %3: %4, no mipmaps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>texture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>base colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (%2 frame)</source>
        <extracomment>%1 the light&apos;s name in bold (Light 2); %2 its frame (camera, world, object)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Light %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>P, L (%1)</source>
        <extracomment>P and L in the light&apos;s own frame: %1 the frame (world, object)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>distance, attenuation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>spot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 (outside the cone)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+5"/>
        <source>ambient</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+5"/>
        <source>diffuse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+5"/>
        <source>specular</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Sum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the model (%1 shading)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 of 255 (the built-in model, %2 shading)</source>
        <extracomment>%1 the colour (r, g, b) of 255; %2 the shading (gouraud, phong, flat)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of 255 (%2 shading)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+3"/>
        <source>reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 draws %2</source>
        <extracomment>%1 the reference&apos;s name; %2 its colour (r, g, b) at the point</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 draws nothing here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GPU drew</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>difference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of 255 from %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 of 255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The equation at this point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>This point is drawn by %1 (side B), which is itself the reference: it is compared with nothing. The numbers above are the built-in model&apos;s, which that program need not follow.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The pixel is compared with what %1 draws at this point; the numbers above are the built-in model&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Program</name>
    <message>
        <location filename="../../render/gl/program.cpp" line="+75"/>
        <source>the vertex shader is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fragment shader is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the vertex shader is %1 KiB; lightbench compiles sources up to %2 KiB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the fragment shader is %1 KiB; lightbench compiles sources up to %2 KiB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+36"/>
        <source>the vertex shader does not compile (the driver gave no reason)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the fragment shader does not compile (the driver gave no reason)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+285"/>
        <source>the program does not link (no reason given)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no position input: the mesh reaches the shader through the attribute at layout(location = 0), or one named aPos, a_position, vPosition, aVertexPosition or position, or with pos or vert in its name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the fragment shader writes no colour: assign gl_FragColor (no #version, #version 100) or declare an out vec4 (#version 300 es, 330 and later)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+69"/>
        <source>a global variable initialised from a uniform or another variable: GLSL ES 1.00 asks for a constant, browsers run it (WebGL warns); lightbench runs this program translated to GLSL 3.30 (the driver said: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+88"/>
        <source>built-in shader &apos;%1&apos; failed:
%2</source>
        <extracomment>%1 a built-in program&apos;s name, %2 its build log</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-8"/>
        <source>built-in shader &apos;%1&apos; lacks a &apos;#define MAX_LIGHTS&apos;, &apos;LIGHT_FACTORS&apos; or &apos;SHOW_CHOICES&apos; line
</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ProgramGuard</name>
    <message>
        <location filename="../../render/pipeline/program_guard.cpp" line="+16"/>
        <source>the driver ran out of memory compiling or drawing this program (limit %1): a macro that doubles itself, or a program too big for it?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>compiling this program and drawing it on small frames took more than %1: an endless or very long loop, or a program too big for the driver?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ProgramTrial</name>
    <message>
        <location filename="../../render/pipeline/program_trial.cpp" line="+26"/>
        <source>%1 s</source>
        <extracomment>a duration in seconds</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 ms</source>
        <extracomment>a duration in milliseconds</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+28"/>
        <source>drawing one frame with this program at %1x%2 would take more than its budget of %3: an endless or very long loop?</source>
        <extracomment>%1x%2 the frame&apos;s size in pixels, %3 the budget of one frame (&quot;2.0 s&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>drawing one frame with this program at %1x%2 would take more than its budget of %3: too much work for every pixel?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::RecentFiles</name>
    <message>
        <location filename="../../widgets/recent_files.cpp" line="+55"/>
        <source>(none yet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Clear the list</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::SafeWrite</name>
    <message>
        <location filename="../../render/model/io/safe_write.cpp" line="+57"/>
        <location line="+14"/>
        <source>a loop of symbolic links</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not a regular file (a device, a pipe or a folder); not replaced</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>read-only (mode %1); not replaced</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the folder %1 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is not a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot write in %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+127"/>
        <source>no image to write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the PNG could not be encoded</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Scene</name>
    <message>
        <location filename="../../render/model/scene/scene.cpp" line="+391"/>
        <source>cube</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sphere</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>torus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>plane</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::SceneActions</name>
    <message>
        <location filename="../../app/window/scene_actions.cpp" line="+34"/>
        <source>Scenes (*.lbscene *.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Scenes (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lightbench scenes (*.lbscene)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Open Recent S&amp;cene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Gouraud vs Phong (the slides)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phong vs Blinn-Phong specular</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The three light frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The normal matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toon shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The terms one at a time (keys A, D, S)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attenuation of a point light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A spotlight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The exercise: a textured cube and a sphere, light in camera coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A light in one object&apos;s frame (it turns with the torus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture filtering: nearest, linear and mipmaps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exercise: per-fragment lighting (Check My Work, F9)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Open Scene...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>E&amp;xamples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Save Scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save Scene &amp;As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+S</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>E&amp;xport Image...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cop&amp;y Image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+C</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The scene could not be opened; nothing changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+41"/>
        <source>%n field(s) could not be used and kept their defaults:</source>
        <translation>
            <numerusform>%n field could not be used and kept their defaults:</numerusform>
            <numerusform>%n fields could not be used and kept their defaults:</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This step opened with less tessellation than it asks for, to fit this machine&apos;s memory; the file is unchanged unless you save the scene.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 opened with less tessellation than it asks for, to fit this machine&apos;s memory; the file is unchanged unless you save the scene.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>This step opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>This step opened; %n field could not be used and kept their defaults.</numerusform>
            <numerusform>This step opened; %n fields could not be used and kept their defaults.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>%1 opened; %n field could not be used and kept their defaults.</numerusform>
            <numerusform>%1 opened; %n fields could not be used and kept their defaults.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Opened the scene %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The scene was not saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved the scene to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: not drawn: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the view could not be drawn at %2 x %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The image was not exported.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Copied the view (%1 x %2) to the clipboard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Open a scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Save the scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export the view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PNG images (*.png);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Scene</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::SceneBudget</name>
    <message>
        <location filename="../../render/model/mesh/scene_budget.cpp" line="+60"/>
        <location line="+2"/>
        <source>%1 million</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+15"/>
        <source>%n object(s) at tessellation %1 would make %2 triangles (~%3)</source>
        <extracomment>what a scene asks for; %n the objects in the scene</extracomment>
        <translation>
            <numerusform>%n object at tessellation %1 would make %2 triangles (~%3)</numerusform>
            <numerusform>%n objects at tessellation %1 would make %2 triangles (~%3)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n object(s) at tessellation up to %1 would make %2 triangles (~%3)</source>
        <translation>
            <numerusform>%n object at tessellation up to %1 would make %2 triangles (~%3)</numerusform>
            <numerusform>%n objects at tessellation up to %1 would make %2 triangles (~%3)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>tessellation lowered to %1 on %n object(s) (%2) to fit %3, the most a scene may take on this machine (%4 of memory): %5 triangles now</source>
        <extracomment>what was done about it; %n the objects lowered, %2 their names</extracomment>
        <translation>
            <numerusform>tessellation lowered to %1 on %n object (%2) to fit %3, the most a scene may take on this machine (%4 of memory): %5 triangles now</numerusform>
            <numerusform>tessellation lowered to %1 on %n objects (%2) to fit %3, the most a scene may take on this machine (%4 of memory): %5 triangles now</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>tessellation lowered to %1 on %n object(s) (%2) and still over %3, the most a scene may take on this machine (%4 of memory): ~%5 (its mesh files count in full)</source>
        <translation>
            <numerusform>tessellation lowered to %1 on %n object (%2) and still over %3, the most a scene may take on this machine (%4 of memory): ~%5 (its mesh files count in full)</numerusform>
            <numerusform>tessellation lowered to %1 on %n objects (%2) and still over %3, the most a scene may take on this machine (%4 of memory): ~%5 (its mesh files count in full)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1; %2</source>
        <extracomment>what a scene asked for (%1) and what was lowered to fit it in memory (%2)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+105"/>
        <source>%1 GB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 MB</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::SceneFile</name>
    <message>
        <location filename="../../render/model/scene/scene_file.cpp" line="-161"/>
        <source>not true or false; read as false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+56"/>
        <source>%1: not a scene file: %2 at byte %3</source>
        <extracomment>%1 a path, %2 Qt&apos;s JSON parser&apos;s reason</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: not a scene file: the JSON is not an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: a lesson file, not a scene file (open it as a lesson)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>expected &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>missing or not a number; read as %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>newer than this lightbench&apos;s %1: what it does not know is left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>needs vertex and fragment sources as strings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the vertex shader has %1 characters, more than a shader may have (%2)</source>
        <extracomment>%1 the shader&apos;s characters; %2 the most a shader may have</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the fragment shader has %1 characters, more than a shader may have (%2)</source>
        <extracomment>%1 the shader&apos;s characters; %2 the most a shader may have</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 (the section is kept as it is)</source>
        <extracomment>%1 why an exercise section cannot be graded against</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::SceneJson</name>
    <message>
        <location filename="../../render/model/scene/scene_json.cpp" line="+230"/>
        <source>not one of the values the scene feeds (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+76"/>
        <location line="+33"/>
        <source>not an array</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-29"/>
        <source>at most 4 lights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../../render/model/scene/scene_json_reader.cpp" line="+24"/>
        <source>not an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>empty: one object drawn instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>at most 32 objects; the rest left out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not an object; a sphere in its place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>no such object; the first one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-159"/>
        <location line="+187"/>
        <source>too many: %1 more than the %2 kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-180"/>
        <location line="+187"/>
        <source>not a uniform&apos;s name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>not 1 to 4 numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/model/scene/scene_json_reader.cpp" line="-9"/>
        <source>%1 (%2)</source>
        <extracomment>a field of a scene file as the file spells it (%1, &quot;lights[2].frame&quot;, never translated) and why it was not used (%2)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>unknown field</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+49"/>
        <source>not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not an array of numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+9"/>
        <source>out of range, clamped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not true or false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not a string</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+0"/>
        <source>not a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>unknown value</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ScenePanel</name>
    <message>
        <location filename="../../widgets/scene_panel.cpp" line="+84"/>
        <source>%1 or %2</source>
        <extracomment>uniform names, one of which a shader may declare: %1 the first ones, comma-separated; %2 the last</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Unused: the program on screen has no uniform %1 (a constant in the shader, perhaps), so this control changes nothing.

%2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ScenePhrases</name>
    <message>
        <location filename="../../app/window/scene_phrases.cpp" line="+29"/>
        <source>showing normal</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws N as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing light</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws L (towards the light) as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing view</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws V (towards the eye) as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing half</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws H, the half vector, as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing reflect</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws R, the reflected light, as a colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing ndotl</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws N·L as grey (&quot;ndotl&quot; is its name in files)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing specular</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws the specular factor as grey</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>showing attenuation</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws a point light&apos;s attenuation as grey</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>directional light in the camera frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the camera frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>directional light in the world frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the world frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>directional light in the object frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the object frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>%n light(s) on</source>
        <translation>
            <numerusform>%n light on</numerusform>
            <numerusform>%n lights on</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the program&apos;s own light (marker hidden)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Program: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>drawn flat (per triangle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 specular</source>
        <extracomment>%1 the specular model&apos;s name and cosine: &quot;Blinn-Phong (N·H)&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, %2</source>
        <extracomment>joins the status line&apos;s clauses about the program: &quot;Program: toon.vert, drawn flat&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>perspective projection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>orthographic projection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1  |  %2  |  %3</source>
        <extracomment>the status line&apos;s three places: the program, the light, the projection</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::SettingsAutosave</name>
    <message>
        <location filename="../../app/window/settings_autosave.cpp" line="+20"/>
        <source>%1 is not a settings file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 cannot be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Your work is saved again in %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Your work is not saved, trying again every %1 s: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::SettingsStore</name>
    <message>
        <location filename="../../app/window/settings_store.cpp" line="-24"/>
        <source>no temporary folder for the settings (%1): they are written directly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: cannot be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: its scratch copy %2 cannot be written (a full temporary folder?)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ShaderDocument</name>
    <message>
        <location filename="../../render/model/scene/shader_document.cpp" line="+204"/>
        <source>Cannot open %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Cannot save %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The shaders have no files yet: use Save As</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ShaderEditor</name>
    <message>
        <location filename="../../widgets/shader_editor.cpp" line="+137"/>
        <source>error: %1</source>
        <extracomment>a compiler&apos;s message under its line in the editor; %1 the message</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>warning: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ShadingPanel</name>
    <message>
        <location filename="../../widgets/shading_panel.cpp" line="+27"/>
        <source>Gouraud (per vertex)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Phong (per fragment)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flat (per triangle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gouraud: the model runs in the vertex shader and colours are interpolated; Phong: N, L, V are interpolated and the model runs for every fragment; flat: each triangle takes the colour of its last (provoking) vertex (key G: Gouraud / Phong)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>R = reflect(-L, N), the mirrored light direction; H = normalize(L + V), the half vector (key B)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <extracomment>the specular model&apos;s name and its factor: &quot;Phong: (R·V)^n&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+44"/>
        <source>Specular</source>
        <extracomment>the row of the specular term&apos;s choice (Phong or Blinn-Phong)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-42"/>
        <source>Perspective: V = -posC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Orthographic: V = (0,0,1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mProjection, and the view vector V that matches it (key P)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Projection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Colour (lit)</source>
        <extracomment>what the surface shows: the lit colour, or a vector (N, L, V, H, R) or number as colour</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>N as colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>L as colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>V as colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>H as colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R as colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>N·L as grey</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specular factor as grey</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Attenuation as grey</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uShow: the model taken apart. Vectors as 0.5·v + 0.5 (x red, y green, z blue), numbers as grey; L, H, R and the numbers are light 1&apos;s (with several lights on too)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Show</source>
        <extracomment>the row of the Show choice (what the surface shows)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Lighting</source>
        <extracomment>a switch: the lighting model on, or Kd unlit</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>uEnableLighting: off shows Kd unlit (key L)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Multiply ambient and diffuse by the vertex colour (vColor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ambient</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ia·Ka: uEnableAmbient (key A)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Id·Kd·max(N·L, 0): uEnableDiffuse (key D)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Is·Ks·(R·V or N·H)^n: uEnableSpecular (key S)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Terms</source>
        <extracomment>the row of the ambient, diffuse and specular terms&apos; switches</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Normals by the model-view (wrong)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transform normals by mModelView instead of its inverse transpose, to see why the normal matrix exists: under a non-uniform scale the normals tilt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Compare&lt;/b&gt; side A with side B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Side A is the program on screen (the editor&apos;s); side B is the built-in program with the choices below, a shader pair from files, or an open exercise&apos;s reference; one camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Files...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B draws a shader pair from files (NAME.vert and NAME.frag), e.g. last week&apos;s solution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop using these files: side B draws what it drew before them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>B program</source>
        <extracomment>the program side B of the compare view draws (A and B are the two sides)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Off</source>
        <extracomment>the compare view is off (A alone)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Side by side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+34"/>
        <source>Wipe</source>
        <extracomment>the row of the slider that places the wipe&apos;s dividing line</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-34"/>
        <source>Difference |A - B|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side by side: A left, B right; wipe: drag the line in the view; difference: |A - B| as a heat map (key C cycles)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>View</source>
        <extracomment>the compare view (off, side by side, wipe, difference); not the menu, not the camera</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B: Gouraud</source>
        <extracomment>side B&apos;s shading (B is the compare view&apos;s second side)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>B: Phong</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>B: Flat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B&apos;s shading: per vertex or per fragment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>B shading</source>
        <extracomment>side B&apos;s shading (B is the compare view&apos;s second side)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B&apos;s specular term</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>B: %1</source>
        <extracomment>side B&apos;s specular model (B is the compare view&apos;s second side): &quot;B: Phong (R·V)&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>B specular</source>
        <extracomment>side B&apos;s specular term (B is the compare view&apos;s second side)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Where the wipe divides A (left) from B (right)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reset shading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phong shading, Blinn-Phong specular, perspective, lighting on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the built-in program</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Submission</name>
    <message>
        <location filename="../../app/common/submission.cpp" line="+72"/>
        <source>%1: a folder needs one NAME.vert and one NAME.frag (it has %2 and %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: the scene file has no program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: the scene file&apos;s program cannot be used: %2</source>
        <extracomment>%2 why the scene&apos;s program was not used (&quot;program (the vertex shader has ... characters, ...)&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: no %2 beside it (a submission is NAME.vert and NAME.frag)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::TextureControls</name>
    <message>
        <location filename="../../widgets/texture_controls.cpp" line="+28"/>
        <source>Texture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uEnableTexture: multiply ambient and diffuse by the texture (uSampler): the image file, else the mesh file&apos;s diffuse texture, else the checker</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Image...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a PNG, JPEG or any image Qt reads as this object&apos;s texture (Ctrl+T, or drop it on the window); at most %1 x %1 texels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No image: back to the mesh file&apos;s texture or the checker</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Repeat</source>
        <extracomment>texture wrapping: GL_REPEAT or GL_CLAMP_TO_EDGE</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Clamp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Texture coordinates outside 0 to 1: the image repeats (GL_REPEAT) or its edge stretches (GL_CLAMP_TO_EDGE)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Nearest</source>
        <extracomment>texture filtering: GL_NEAREST or GL_LINEAR</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Linear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The texel nearest the coordinate (GL_NEAREST: blocky when magnified) or the four around it weighted (GL_LINEAR)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Mipmaps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where the texture is minified, read a smaller copy of it chosen by the level of detail (GL_NEAREST_MIPMAP_NEAREST, or trilinear GL_LINEAR_MIPMAP_LINEAR with the linear filter): no shimmer far away. The probe shows the level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (not shown)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the checker</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the mesh file&apos;s texture, or the checker</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::TextureFile</name>
    <message>
        <location filename="../../render/model/scene/texture_file.cpp" line="+4"/>
        <source>%1: an empty file, not an image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: not an image (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the formats read are %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 x %3 texels is more than a texture may have (%4 x %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <location line="+6"/>
        <source>%1: could not be read as an image: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2 x %3 texels (scaled from %4 x %5)</source>
        <extracomment>%1 a file&apos;s name, %2 x %3 the texels drawn, %4 x %5 the image&apos;s own size</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 x %3 texels</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::TrialProcess</name>
    <message>
        <location filename="../../render/trial/trial_process.cpp" line="+167"/>
        <source>compiling this program and drawing it on small frames did not finish within %1 (the trial&apos;s helper was replaced): an endless or very long loop, or a program too big for the driver?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+40"/>
        <source>the driver ran out of memory compiling or drawing this program (limit %1; the trial&apos;s helper was replaced)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the driver crashed the trial&apos;s helper while it drew this program (it was replaced)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the trial&apos;s helper ended while it drew this program (exit code %1; it was replaced)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::UnfedInputs</name>
    <message>
        <location filename="../../render/glsl/unfed_inputs.cpp" line="+66"/>
        <source>the positions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the normals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the texture coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the vertex colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no array of the mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is at location %2, where the mesh gives %3, though its name says %4 (at location %5 here): write layout(location = %5) to read them</source>
        <extracomment>%1 the input&apos;s name; %2 its location; %3 what the mesh gives there; %4 what its name says; %5 the location that has it</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+47"/>
        <source>the scene feeds nothing to the matrix %1: it stays all zeros, and whatever it multiplies collapses to nothing on screen; bind it to one of %2 (the Bindings tab, or --bind %1=KEY)</source>
        <extracomment>%1 the uniform&apos;s name; %2 the keys it could be bound to (model-view, projection)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the scene feeds nothing to %1: it stays 0 unless you set it in the Uniforms panel; bind it to one of %2 (the Bindings tab, or --bind %1=KEY)</source>
        <extracomment>%1 the uniform&apos;s name; %2 the keys it could be bound to (light-position-world)</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::UniformPanel</name>
    <message>
        <location filename="../../widgets/uniform_panel.cpp" line="+70"/>
        <source>The program has no uniforms of its own. A uniform that no panel feeds gets a control here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The program&apos;s own uniforms; values stay when you recompile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No control for: %1 (matrices, samplers and arrays).</source>
        <extracomment>%1 the names of uniforms that get no control, comma-separated</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::UnsavedWork</name>
    <message>
        <location filename="../../app/window/unsaved_work.cpp" line="+17"/>
        <source>the shader file %1</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the shader files %1 and %2</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;; %1 and %2 are NAME.vert, NAME.frag</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the lesson “%1”</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the untitled scene</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the scene “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 and %2</source>
        <extracomment>the lesson or the scene (%1) and the shader files (%2), in &quot;Save the changes to %1&quot;</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Save the changes to %1 before closing?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before opening “%2”?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before resetting everything?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before closing it?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the changes to %1 before starting a new lesson?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Your changes will be lost if you don&apos;t save them. Save saves them all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Your changes will be lost if you don&apos;t save them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Unsaved changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Discard</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::ViewCoverage</name>
    <message>
        <location filename="../../render/model/measure/view_coverage.cpp" line="+86"/>
        <source>draws nothing in view: every face in view turns its back to the camera, and back faces are culled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>is seen from behind: every face in view turns its back to the camera, lit as from behind (dark); Faces: Both sides lit shows that side lit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>draws nothing in view: it lies outside the view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>draws nothing in view: every face in view turns away from the camera and back faces are culled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>draws nothing in view: it is flat (in the %1 plane) and seen edge-on: turn it or the camera</source>
        <extracomment>%1: the plane the mesh lies in (YZ, XZ, XY)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>draws nothing in view: it covers less than a pixel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::Viewport</name>
    <message>
        <location filename="../../widgets/viewport.cpp" line="+33"/>
        <source>Left drag: orbit - right or middle drag: pan - wheel: zoom - R: reset view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../render/pipeline/program_pipeline.cpp" line="+53"/>
        <source>the OpenGL context was lost while this program drew (the driver reset the GPU: an endless or very long loop?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/viewport.cpp" line="+94"/>
        <source>The renderer could not start:
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/viewport_captions.cpp" line="+20"/>
        <source>The shader has errors (see the editor): the built-in program is drawing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The shader has errors (see the editor): the last good program is drawing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Refused: %1; the built-in program is drawing</source>
        <extracomment>%1 why the program was refused (a loop that never ends, a frame too slow)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Refused: %1; the last good program is drawing</source>
        <extracomment>%1 why the program was refused</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>OpenGL %1, %2; WebGL 1 shaders run as GLSL 3.30</source>
        <extracomment>%1 the OpenGL version (4.5); %2 the driver&apos;s renderer (llvmpipe ...)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>OpenGL %1, %2</source>
        <extracomment>%1 the OpenGL version (4.5); %2 the driver&apos;s renderer</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>B: %1</source>
        <extracomment>side B of the compare view and the program it draws</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the reference program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B: built-in %1, %2</source>
        <extracomment>side B draws the built-in program: %1 its shading, %2 its specular term</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gouraud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phong</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A (left): %1  |  %2 (right)</source>
        <extracomment>side A (left) names its program; %2 says side B&apos;s (&quot;B: ...&quot;), on the right</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+13"/>
        <source>the program on screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-9"/>
        <source>|A - B|: not drawn yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>|A - B|, A: %7, %1: largest %2/255 at (%3, %4); %5% of the drawn pixels within %8/255; scale 0 (black) to %6/255 (white)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (this view, %2 x %3 pixels); %4</source>
        <extracomment>%1 the difference view&apos;s figures; %2 x %3 the view&apos;s size in pixels; %4 what Check My Work measured for the case (its own frame size and figures)</extracomment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::WireReader</name>
    <message>
        <location filename="../../render/import/wire_reader.cpp" line="+50"/>
        <source>the import stream goes on after its end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the import helper wrote something that is not a mesh stream</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the import stream holds two meshes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import stream announces a mesh of a bad size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the import stream holds a record too large to be right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>not enough memory for the mesh (%1 MB received)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>receiving</source>
        <extracomment>a stage of loading a mesh file, shown beside its progress</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the import stream holds an index past the last vertex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the import stream holds coordinates that are not finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the import stream announces a mesh whose sizes don&apos;t add up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the import stream announces a mesh of %1 MB, more than the helper may use (%2 MB)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+40"/>
        <source>the import stream holds a short progress record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the import failed without saying why</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the import stream holds a material of the wrong size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the import stream holds a short texture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the import stream holds a texture whose size doesn&apos;t add up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the import stream ended without a mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the import stream holds a record of unknown type %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>lb::WorkCheck</name>
    <message>
        <location filename="../../app/common/work_check.cpp" line="+42"/>
        <source>killed by signal %1 (%2)</source>
        <extracomment>%2 is the C library&apos;s name of the signal, in English (&quot;Segmentation fault&quot;)</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exit code %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>no temporary folder for the check: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+32"/>
        <source>your program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>more than %1 s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
