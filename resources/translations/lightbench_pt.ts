<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_PT">
<context>
    <name>QFileDialog</name>
    <message>
        <location filename="../../app/common/qt_standard_words.cpp" line="+47"/>
        <source>Look in:</source>
        <translation>Procurar em:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go back</source>
        <translation>Recuar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go forward</source>
        <translation>Avançar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to the parent directory</source>
        <translation>Ir para a pasta acima</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Create a New Folder</source>
        <translation>Criar uma pasta nova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change to list view mode</source>
        <translation>Mostrar em lista</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change to detail view mode</source>
        <translation>Mostrar com detalhes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sidebar</source>
        <translation>Barra lateral</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>List of places and bookmarks</source>
        <translation>Lista de locais e marcadores</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Files</source>
        <translation>Ficheiros</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recent Places</source>
        <translation>Locais recentes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New Folder</source>
        <translation>&amp;Nova pasta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>Apagar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>Remover</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Choose</source>
        <translation>&amp;Escolher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation>Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation>Deseja mesmo apagar &apos;%1&apos;?</translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <location line="+1"/>
        <source>Computer</source>
        <translation>Computador</translation>
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
        <translation>Guardar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save All</source>
        <translation>Guardar Tudo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open</source>
        <translation>Abrir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Yes</source>
        <translation>&amp;Sim</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yes to &amp;All</source>
        <translation>Sim para &amp;Todos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;No</source>
        <translation>&amp;Não</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N&amp;o to All</source>
        <translation>Nã&amp;o para Todos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort</source>
        <translation>Abortar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retry</source>
        <translation>Repetir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ignore</source>
        <translation>Ignorar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>Fechar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard</source>
        <translation>Descartar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Help</source>
        <translation>Ajuda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Repor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore Defaults</source>
        <translation>Repor Predefinições</translation>
    </message>
</context>
<context>
    <name>QShortcut</name>
    <message>
        <location line="+4"/>
        <source>Space</source>
        <translation>Espaço</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Backspace</source>
        <translation>Retrocesso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PgUp</source>
        <translation>Page Up</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PgDown</source>
        <translation>Page Down</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Left</source>
        <translation>Seta Esquerda</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Right</source>
        <translation>Seta Direita</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Up</source>
        <translation>Seta Acima</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Down</source>
        <translation>Seta Abaixo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ins</source>
        <translation>Insert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Del</source>
        <translation>Delete</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return</source>
        <translation>Enter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Print</source>
        <translation>Print Screen</translation>
    </message>
</context>
<context>
    <name>lb::BindingPanel</name>
    <message>
        <location filename="../../widgets/binding_panel.cpp" line="+24"/>
        <source>Vertex positions (location 0)</source>
        <translation>Posições dos vértices (location 0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex normals (location 1)</source>
        <translation>Normais dos vértices (location 1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture coordinates (location 2)</source>
        <translation>Coordenadas de textura (location 2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours (location 3)</source>
        <translation>Cores dos vértices (location 3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Nothing: the mesh has no array at location %1</source>
        <extracomment>%1 the location number a vertex input was linked at</extracomment>
        <translation>Nada: a malha não tem array na location %1</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>A vertex input is fed by its location: layout(location = N), or the slot its name gives (aPos, a_normal, inTexCoord...).</source>
        <translation>Uma entrada de vértice é alimentada pela sua location: layout(location = N), ou o lugar que o seu nome indica (aPos, a_normal, inTexCoord...).</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The built-in program draws: its inputs are the panels&apos;. A program of your own shows each input here with what feeds it, and you can choose what does.</source>
        <translation>O programa incluído desenha: as suas entradas são as dos painéis. Um programa seu mostra aqui cada entrada com o que a alimenta, e pode escolher o que a alimenta.</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n uniform(s) fed nothing: choose what feeds them; the choice is saved with the scene.</source>
        <extracomment>%n how many uniforms nothing feeds</extracomment>
        <translation>
            <numerusform>%n uniform não é alimentado: escolha o que o alimenta; a escolha é guardada com a cena.</numerusform>
            <numerusform>%n uniforms não são alimentados: escolha o que os alimenta; a escolha é guardada com a cena.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What feeds each input of the program, chosen by its name; change a choice to feed another value. The choice is saved with the scene.</source>
        <translation>O que alimenta cada entrada do programa, escolhido pelo seu nome; mude uma escolha para alimentar outro valor. A escolha é guardada com a cena.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>By its name: %1</source>
        <extracomment>the entry that lets the uniform&apos;s name decide what feeds it; %1 what that is</extracomment>
        <translation>Pelo nome: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>By its name: nothing (the name is no convention&apos;s)</source>
        <translation>Pelo nome: nada (o nome não é de nenhuma convenção)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not fed: its own value (the Uniforms panel)</source>
        <translation>Não alimentado: o seu próprio valor (o painel Uniforms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not fed</source>
        <translation>Não alimentado</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Fed with: %1</source>
        <translation>Alimentado com: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fed nothing: it stays 0 and decides the picture. Choose what the scene gives.</source>
        <translation>Nada o alimenta: fica a 0 e decide a imagem. Escolha o que a cena dá.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fed nothing by the scene: its own value (the Uniforms panel&apos;s control, or its initialiser).</source>
        <translation>A cena não o alimenta: o seu próprio valor (o controlo do painel Uniforms, ou o seu inicializador).</translation>
    </message>
</context>
<context>
    <name>lb::Bindings</name>
    <message>
        <location filename="../../render/glsl/bindings.cpp" line="+26"/>
        <source>Model-view matrix (camera from object)</source>
        <translation>Matriz modelview (câmara a partir do objeto)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normal matrix (inverse transpose of model-view)</source>
        <translation>Matriz das normais (inversa transposta da modelview)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>View matrix (camera from world)</source>
        <translation>Matriz de vista (câmara a partir do mundo)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>View&apos;s normal matrix (inverse transpose of view)</source>
        <translation>Matriz das normais da vista (inversa transposta da vista)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection matrix</source>
        <translation>Matriz de projeção</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position, in the Light panel&apos;s frame (x, y, z, w)</source>
        <translation>Posição da luz, no referencial do painel Luz (x, y, z, w)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position (camera coordinates)</source>
        <translation>Posição da luz (coordenadas da câmara)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s ambient colour Ia</source>
        <translation>Cor ambiente da luz Ia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s diffuse colour Id</source>
        <translation>Cor difusa da luz Id</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s specular colour Is</source>
        <translation>Cor especular da luz Is</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s ambient colour Ka</source>
        <translation>Cor ambiente do material Ka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s diffuse colour Kd</source>
        <translation>Cor difusa do material Kd</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Material&apos;s specular colour Ks</source>
        <translation>Cor especular do material Ks</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shininess</source>
        <translation>Brilho</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light&apos;s frame (0 camera, 1 world, 2 object)</source>
        <translation>Referencial da luz (0 câmara, 1 mundo, 2 objeto)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light on (1) or off (0)</source>
        <translation>Luz ligada (1) ou desligada (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Specular model (0 Phong, 1 Blinn-Phong)</source>
        <translation>Modelo especular (0 Phong, 1 Blinn-Phong)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection (0 perspective, 1 parallel)</source>
        <translation>Projeção (0 perspetiva, 1 paralela)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lighting on (1) or off (0)</source>
        <translation>Iluminação ligada (1) ou desligada (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours on (1) or off (0)</source>
        <translation>Cores dos vértices ligadas (1) ou desligadas (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture on (1) or off (0)</source>
        <translation>Textura ligada (1) ou desligada (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The object&apos;s texture (unit 0)</source>
        <translation>A textura do objeto (unidade 0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation (kc, kl, kq)</source>
        <translation>Atenuação (kc, kl, kq)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s axis, in the light&apos;s frame</source>
        <translation>Eixo do foco, no referencial da luz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s cut-off angle (degrees)</source>
        <translation>Ângulo de corte do foco (graus)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cosine of the spot&apos;s cut-off angle</source>
        <translation>Cosseno do ângulo de corte do foco</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s exponent</source>
        <translation>Expoente do foco</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ambient term on (1) or off (0)</source>
        <translation>Termo ambiente ligado (1) ou desligado (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse term on (1) or off (0)</source>
        <translation>Termo difuso ligado (1) ou desligado (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Specular term on (1) or off (0)</source>
        <translation>Termo especular ligado (1) ou desligado (0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show choice (0 the colour, 1 N, 2 L...)</source>
        <translation>Escolha do que mostrar (0 a cor, 1 N, 2 L...)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Model matrix (world from object)</source>
        <translation>Matriz do modelo (mundo a partir do objeto)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Model&apos;s normal matrix (inverse transpose of model)</source>
        <translation>Matriz das normais do modelo (inversa transposta do modelo)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection times view</source>
        <translation>Projeção vezes vista</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Projection times model-view (MVP)</source>
        <translation>Projeção vezes modelview (MVP)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light position (world coordinates)</source>
        <translation>Posição da luz (coordenadas do mundo)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Direction the light shines (world)</source>
        <translation>Direção em que a luz brilha (mundo)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Direction towards the light (world, unit)</source>
        <translation>Direção para a luz (mundo, unitária)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Camera position (world coordinates)</source>
        <translation>Posição da câmara (coordenadas do mundo)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ia times Ka</source>
        <translation>Ia vezes Ka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Id times Kd</source>
        <translation>Id vezes Kd</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Is times Ks</source>
        <translation>Is vezes Ks</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s constant factor kc</source>
        <translation>Fator constante da atenuação kc</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s linear factor kl</source>
        <translation>Fator linear da atenuação kl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attenuation&apos;s quadratic factor kq</source>
        <translation>Fator quadrático da atenuação kq</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot&apos;s axis (camera coordinates)</source>
        <translation>Eixo do foco (coordenadas da câmara)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Half vector of a viewer far along +z (camera coordinates)</source>
        <translation>Vetor médio de um observador distante ao longo de +z (coordenadas da câmara)</translation>
    </message>
    <message>
        <location line="+126"/>
        <source>the binding %1=%2 is not used: %1 is not of the type that %2 gives (a matrix, numbers, a texture)</source>
        <extracomment>%1 the uniform&apos;s name, %2 the key chosen for it (model-view, light-diffuse)</extracomment>
        <translation>a ligação %1=%2 não é usada: %1 não é do tipo que %2 dá (uma matriz, números, uma textura)</translation>
    </message>
</context>
<context>
    <name>lb::BoundedRead</name>
    <message>
        <location filename="../../render/model/io/bounded_read.cpp" line="+35"/>
        <location line="+6"/>
        <source>no such file</source>
        <translation>ficheiro inexistente</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>a loop of symbolic links</source>
        <translation>um ciclo de ligações simbólicas</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a symbolic link to %1, which does not exist</source>
        <translation>uma ligação simbólica para %1, que não existe</translation>
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
        <translation>%1: não é um ficheiro regular (é uma pasta, um dispositivo ou um pipe)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 is more than %3 may be (%4)</source>
        <extracomment>%1 a path, %2 its size, %3 a kind of file (&quot;a scene file&quot;), %4 the limit (&quot;64 MB&quot;)</extracomment>
        <translation>%1: %2 é mais do que %3 pode ter (%4)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: more than %2 may be (%3)</source>
        <extracomment>%1 a path, %2 a kind of file (&quot;a scene file&quot;), %3 the limit (&quot;64 MB&quot;)</extracomment>
        <translation>%1: mais do que %2 pode ter (%3)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: not saved: %2 would take %3, more than %4 may be (%5), so it could not be opened again</source>
        <extracomment>%1 a path, %2 what is saved (&quot;the scene&quot;), %3 its size, %4 a kind of file (&quot;a scene file&quot;), %5 the limit (&quot;64 MB&quot;)</extracomment>
        <translation>%1: não guardado: %2 ocuparia %3, mais do que %4 pode ter (%5), pelo que não se poderia voltar a abri-lo</translation>
    </message>
</context>
<context>
    <name>lb::CaptionDialog</name>
    <message>
        <location filename="../../widgets/caption_dialog.cpp" line="+21"/>
        <source>English</source>
        <translation>Inglês</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Portuguese</source>
        <translation>Português</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>German</source>
        <translation>Alemão</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+43"/>
        <source>Edit Caption</source>
        <translation>Editar Legenda</translation>
    </message>
    <message>
        <location line="-41"/>
        <source>What the class reads under the view. Markdown: *italic*, **bold**, `code`, lists. An empty language shows English.</source>
        <translation>O que a turma lê por baixo da vista. Markdown: *itálico*, **negrito**, `código`, listas. Um idioma vazio mostra o inglês.</translation>
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
        <translation>A legenda (%1) tem %2 carateres; uma legenda tem no máximo %3. Ainda nada foi alterado: encurte-a, ou Cancelar.</translation>
    </message>
</context>
<context>
    <name>lb::ChoiceLabels</name>
    <message>
        <location filename="../../widgets/choice_labels.cpp" line="+14"/>
        <source>camera</source>
        <comment>light frame</comment>
        <translation>câmara</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>world</source>
        <comment>light frame</comment>
        <translation>mundo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>object</source>
        <comment>light frame</comment>
        <translation>objeto</translation>
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
        <translation>plano</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>colour</source>
        <comment>show</comment>
        <translation>a cor iluminada</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>normal</source>
        <comment>show</comment>
        <extracomment>the normal N, drawn as a colour</extracomment>
        <translation>a normal N</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>light</source>
        <comment>show</comment>
        <extracomment>the light vector L, drawn as a colour</extracomment>
        <translation>o vetor da luz L</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>view</source>
        <comment>show</comment>
        <extracomment>the view vector V, drawn as a colour</extracomment>
        <translation>o vetor de observação V</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>half</source>
        <comment>show</comment>
        <extracomment>the half vector H, drawn as a colour</extracomment>
        <translation>o vetor médio H</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>reflect</source>
        <comment>show</comment>
        <extracomment>the reflected light R, drawn as a colour</extracomment>
        <translation>o vetor de reflexão R</translation>
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
        <translation>o fator especular</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>attenuation</source>
        <comment>show</comment>
        <extracomment>the attenuation drawn as grey</extracomment>
        <translation>a atenuação</translation>
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
        <translation>Escolher %1 com o diálogo de cores</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1, %2 channel (0 to 1)</source>
        <translation>%1, canal %2 (0 a 1)</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Choose %1</source>
        <translation>Escolher %1</translation>
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
        <translation>|A-B| de 255</translation>
    </message>
</context>
<context>
    <name>lb::EditorPanel</name>
    <message>
        <location filename="../../widgets/editor_panel.cpp" line="+41"/>
        <source>vertex</source>
        <extracomment>the shader stage a message is about, before its line:column</extracomment>
        <translation>vértices</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>fragment</source>
        <extracomment>the shader stage a message is about, before its line:column</extracomment>
        <translation>fragmentos</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>link</source>
        <extracomment>a message of the linker, about no single stage</extracomment>
        <translation>ligação</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the scene&apos;s shaders</source>
        <translation>os shaders da cena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>your shaders</source>
        <translation>os seus shaders</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (edited)</source>
        <translation>%1 (editado)</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+137"/>
        <source>Presets</source>
        <translation>Predefinições</translation>
    </message>
    <message>
        <location line="-129"/>
        <source>Presets: the built-in programs, the slides&apos; shaders as printed, toon</source>
        <translation>Predefinições: os programas integrados, os shaders dos diapositivos tal como impressos, toon</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Compile</source>
        <translation>Compilar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compile and link now (Ctrl+Enter)</source>
        <translation>Compilar e ligar (link) agora (Ctrl+Enter)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Live</source>
        <extracomment>recompile while typing (a switch)</extracomment>
        <translation>Ao vivo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recompile after a pause in typing; off: only on Ctrl+Enter</source>
        <translation>Recompilar após uma pausa na escrita; desligado: só com Ctrl+Enter</translation>
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
        <translation>A pausa após a última tecla antes de uma recompilação ao vivo (a roda do rato ou as setas alteram-na)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Find (Ctrl+F)</source>
        <translation>Procurar (Ctrl+F)</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+148"/>
        <source>Vertex</source>
        <translation>Vértices</translation>
    </message>
    <message>
        <location line="-147"/>
        <location line="+150"/>
        <source>Fragment</source>
        <translation>Fragmentos</translation>
    </message>
    <message>
        <location line="-144"/>
        <source>Click a message to go to its line</source>
        <translation>Clique numa mensagem para ir para a sua linha</translation>
    </message>
    <message>
        <location line="+125"/>
        <source>%1 is gone from the disk; your text is kept</source>
        <translation>%1 desapareceu do disco; o seu texto é mantido</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 changed on disk; your unsaved edits are kept (Open it again to take the disk&apos;s version)</source>
        <translation>%1 mudou no disco; as suas edições por guardar são mantidas (abra-o de novo para usar a versão do disco)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Vertex - %1</source>
        <extracomment>the vertex shader&apos;s tab; %1 its file&apos;s name</extracomment>
        <translation>Vértices - %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fragment - %1</source>
        <extracomment>the fragment shader&apos;s tab; %1 its file&apos;s name</extracomment>
        <translation>Fragmentos - %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Your unsaved shader edits from the last session are back</source>
        <translation>As suas edições dos shaders por guardar da última sessão foram recuperadas</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>%1  error: %2</source>
        <extracomment>%1 where (fragment 5:3); %2 the compiler&apos;s message</extracomment>
        <translation>%1  erro: %2</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1  warning: %2</source>
        <translation>%1  aviso: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>linked, %n warning(s)</source>
        <translation>
            <numerusform>ligado, %n aviso</numerusform>
            <numerusform>ligado, %n avisos</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linked</source>
        <translation>ligado</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n error(s): last good program drawing</source>
        <translation>
            <numerusform>%n erro: o último programa válido continua a desenhar</numerusform>
            <numerusform>%n erros: o último programa válido continua a desenhar</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lb::Exercise</name>
    <message>
        <location filename="../../render/model/scene/exercise.cpp" line="+84"/>
        <source>not a number of points from 0 to %1, nor a list of one per case</source>
        <extracomment>%1 the largest number of points (&quot;1000000&quot;)</extracomment>
        <translation>nem um número de pontos de 0 a %1, nem uma lista com um por caso</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>each case&apos;s points must be a number from 0 to %1</source>
        <translation>os pontos de cada caso devem ser um número de 0 a %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 values for %2 cases (one per case)</source>
        <extracomment>%1 how many points the list gives, %2 how many cases the exercise has</extracomment>
        <translation>%1 valores para %2 casos (um por caso)</translation>
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
        <translation>%1: não é um objeto</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+38"/>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="+55"/>
        <location line="+11"/>
        <location line="+20"/>
        <source>unknown field</source>
        <translation>campo desconhecido</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>%1: needs both a vertex and a fragment shader</source>
        <translation>%1: precisa de um vertex shader e de um fragment shader</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+5"/>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="-51"/>
        <source>not %1</source>
        <extracomment>%1 the words a file may give, as it spells them (&quot;phong, gouraud, flat&quot;)</extracomment>
        <translation>não é nenhum destes: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: no reference program (&quot;reference&quot;: {&quot;vertex&quot;: ..., &quot;fragment&quot;: ...} or {&quot;builtIn&quot;: {...}})</source>
        <translation>%1: sem programa de referência (&quot;reference&quot;: {&quot;vertex&quot;: ..., &quot;fragment&quot;: ...} ou {&quot;builtIn&quot;: {...}})</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a number</source>
        <translation>não é um número</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of range, clamped</source>
        <translation>fora do intervalo, ajustado ao limite</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>not [width, height] in whole pixels, 16 to %1</source>
        <translation>não é [largura, altura] em píxeis inteiros, de 16 a %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not a list of parameters; all of them vary</source>
        <translation>não é uma lista de parâmetros; todos variam</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no such parameter &apos;%1&apos;; those are %2</source>
        <translation>o parâmetro &apos;%1&apos; não existe; os parâmetros válidos são %2</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/exercise_mistakes.cpp" line="+11"/>
        <source>not true or false</source>
        <translation>não é true nem false</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+17"/>
        <source>not an object</source>
        <translation>não é um objeto</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>not a name of 1 to %1 characters; the mistake is left out</source>
        <translation>não é um nome de 1 a %1 carateres; o erro é posto de parte</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>no usable hint; the mistake is left out</source>
        <translation>sem sugestão utilizável; o erro é posto de parte</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>not a shader&apos;s text of up to 1 MiB; the mistake is left out</source>
        <translation>não é o texto de um shader de até 1 MiB; o erro é posto de parte</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>both a program and a built-in; the mistake is left out</source>
        <translation>é ao mesmo tempo um programa e um integrado; o erro é posto de parte</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needs both a vertex and a fragment shader: the reference is the built-in program; the mistake is left out</source>
        <translation>precisa de um vertex e de um fragment shader: a referência é o programa integrado; o erro é posto de parte</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>neither a program (&quot;vertex&quot;, &quot;fragment&quot;) nor &quot;builtIn&quot;: {...}; the mistake is left out</source>
        <translation>não é um programa (&quot;vertex&quot;, &quot;fragment&quot;) nem &quot;builtIn&quot;: {...}; o erro é posto de parte</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a built-in mistake needs a built-in reference; give the mistake as a program; the mistake is left out</source>
        <translation>um erro incorporado precisa de uma referência incorporada; dê o erro como programa; o erro é posto de parte</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a list</source>
        <translation>não é uma lista</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>more than %1 mistakes; the rest are left out</source>
        <translation>mais de %1 erros; os restantes são postos de parte</translation>
    </message>
</context>
<context>
    <name>lb::ExercisePanel</name>
    <message>
        <location filename="../../widgets/exercise_panel.cpp" line="+35"/>
        <source>light position</source>
        <translation>posição da luz</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>point or directional</source>
        <translation>pontual ou direcional</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>light frame</source>
        <translation>referencial da luz</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>light colours</source>
        <translation>cores da luz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>material</source>
        <translation>material</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>camera</source>
        <translation>câmara</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>projection</source>
        <translation>projeção</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>non-uniform scale</source>
        <translation>escala não uniforme</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>nothing (every case is the scene as it is)</source>
        <translation>nada (cada caso é a cena tal como está)</translation>
    </message>
    <message>
        <location line="+30"/>
        <location line="+141"/>
        <source>Check my work</source>
        <translation>Verificar o meu trabalho</translation>
    </message>
    <message>
        <location line="-140"/>
        <source>Draws the exercise&apos;s cases with the program in the editor and with the reference, as the teacher&apos;s grading does, and lists each case (F9)</source>
        <translation>Desenha os casos do exercício com o programa do editor e com a referência, como faz a avaliação do professor, e lista cada caso (F9)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Out of date: the program in the editor has changed since this check. Check my work (F9) checks it as it is now.</source>
        <translation>Desatualizado: o programa no editor mudou desde esta verificação. Verificar o meu trabalho (F9) verifica-o tal como está agora.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Case</source>
        <translation>Caso</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Resultado</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Largest</source>
        <translation>Maior</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Within</source>
        <translation>Dentro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The largest difference of a channel, out of 255</source>
        <translation>A maior diferença num canal, numa escala de 255</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Click a case to see it in the difference view</source>
        <translation>Clique num caso para o ver na vista de diferença</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Back to my scene</source>
        <translation>Voltar à minha cena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The scene as it was before a case was shown</source>
        <translation>A cena tal como estava antes de se mostrar um caso</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>No exercise is open</source>
        <translation>Nenhum exercício aberto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An exercise is a scene file with a task, the teacher&apos;s reference program and how it is graded. File &gt; Examples &gt; &quot;Exercise: per-fragment lighting&quot; is one; File &gt; Open Scene opens others.</source>
        <translation>Um exercício é um ficheiro de cena com um enunciado, o programa de referência do professor e a forma como é avaliado. Ficheiro &gt; Exemplos &gt; &quot;Exercício: iluminação por fragmento&quot; é um deles; Ficheiro &gt; Abrir Cena abre outros.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The share of the pixels either program draws that are within %1/255 of the reference, at %2 x %3: the difference view counts a case alike (at its own size)</source>
        <translation>A percentagem dos píxeis desenhados por qualquer dos programas que diferem no máximo %1/255 da referência, a %2 x %3: a vista de diferença conta um caso da mesma forma (no seu próprio tamanho)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Exercise</source>
        <translation>Exercício</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This exercise cannot be checked: its reference is missing or unusable.</source>
        <translation>Este exercício não pode ser verificado: a sua referência falta ou não pode ser usada.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference: the built-in program, %1 shading, %2 specular.</source>
        <extracomment>%1 the shading (gouraud, phong, flat); %2 the specular term (phong, blinn)</extracomment>
        <translation>Referência: o programa integrado, sombreamento %1, especular %2.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reference: the teacher&apos;s program (not shown; it is side B of the compare views, key C).</source>
        <translation>Referência: o programa do professor (não mostrado; é o lado B das vistas de comparação, tecla C).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 cases at %2 x %3 pixels; a case passes when %4 of its pixels are within %5/255. The cases vary: %6.</source>
        <translation>%1 casos a %2 x %3 píxeis; um caso passa quando %4 dos seus píxeis diferem no máximo %5/255. Os casos variam: %6.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>One frame of your program may take at most %1; a program that would take longer is refused.</source>
        <translation>Um fotograma do seu programa pode demorar no máximo %1; um programa que demore mais é recusado.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cancel the check</source>
        <translation>Cancelar a verificação</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Checking: the cases are drawn with your program and the reference...</source>
        <translation>A verificar: os casos são desenhados com o seu programa e com a referência...</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Your program does not compile:
%1</source>
        <extracomment>%1 the compiler&apos;s messages</extracomment>
        <translation>O seu programa não compila:
%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Your program does not compile</source>
        <translation>O seu programa não compila</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Your program does not link:
%1</source>
        <extracomment>%1 the linker&apos;s messages</extracomment>
        <translation>A ligação (link) do seu programa falhou:
%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Your program does not link</source>
        <translation>A ligação (link) do seu programa falhou</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Your program was refused:
%1</source>
        <extracomment>%1 why it was refused (a loop that never ends, a frame too slow)</extracomment>
        <translation>O seu programa foi recusado:
%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Your program was refused</source>
        <translation>O seu programa foi recusado</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This exercise cannot check your work: one of the known mistakes it lists cannot be drawn. Tell your teacher:
%1</source>
        <extracomment>%1 which of the exercise&apos;s known mistakes, and why (the driver&apos;s words)</extracomment>
        <translation>Este exercício não consegue verificar o seu trabalho: um dos erros conhecidos que indica não pode ser desenhado. Avise o seu professor:
%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The check could not start:
%1</source>
        <extracomment>%1 why the checking process did not start</extracomment>
        <translation>Não foi possível iniciar a verificação:
%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The check could not start</source>
        <translation>Não foi possível iniciar a verificação</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not checked: %1:
%2</source>
        <extracomment>%1 the grading&apos;s status word (English, as the report has it); %2 its reason</extracomment>
        <translation>Não verificado: %1:
%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: %1</source>
        <translation>Não verificado: %1</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>Your failing cases match the exercise&apos;s known mistake &quot;%1&quot; in %2 of their pixels, far more than they match the reference</source>
        <extracomment>%1 the mistake&apos;s name as the exercise gives it (data, English); %2 a share (&quot;98.5%&quot;)</extracomment>
        <translation>Os seus casos falhados coincidem com o erro conhecido &quot;%1&quot; do exercício em %2 dos seus píxeis, muito mais do que com a referência</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Check My Work, at %1 x %2: largest %3/255, %4 within %5/255</source>
        <extracomment>the difference view&apos;s caption for a case of the list; %1 x %2 the check&apos;s frame</extracomment>
        <translation>Verificar o meu trabalho, a %1 x %2: maior %3/255, %4 dentro de %5/255</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Check My Work, at %1 x %2: nothing drawn</source>
        <translation>Verificar o meu trabalho, a %1 x %2: nada desenhado</translation>
    </message>
    <message>
        <location line="-93"/>
        <source>The check took too long (%1) and was stopped</source>
        <extracomment>%1 how long it was given</extracomment>
        <translation>A verificação demorou demasiado (%1) e foi interrompida</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Passed: all %1 cases (in each, at least %2 of the pixels within %3/255); largest difference %4/255</source>
        <translation>Passou: todos os %1 casos (em cada um, pelo menos %2 dos píxeis com diferença até %3/255); maior diferença %4/255</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Not yet: %1 of %2 cases pass; largest difference %3/255</source>
        <translation>Ainda não: %1 de %2 casos passam; maior diferença %3/255</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Click a case to see it in the difference view.</source>
        <translation>Clique num caso para o ver na vista de diferença.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (as given)</source>
        <extracomment>case 0 of the list: the exercise&apos;s scene as it is, not varied</extracomment>
        <translation>%1 (tal como dado)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>passed</source>
        <translation>passou</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>failed</source>
        <translation>falhou</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nothing drawn</source>
        <translation>nada desenhado</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Largest difference at (%1, %2) of the %3 x %4 frame; %5 pixels drawn</source>
        <translation>Maior diferença em (%1, %2) do fotograma de %3 x %4; %5 píxeis desenhados</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 pixels drawn</source>
        <translation>%1 píxeis desenhados</translation>
    </message>
</context>
<context>
    <name>lb::ExportSizeDialog</name>
    <message>
        <location filename="../../widgets/export_size_dialog.cpp" line="+12"/>
        <source>Export Image</source>
        <translation>Exportar Imagem</translation>
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
        <translation>Largura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height</source>
        <translation>Altura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The view is drawn again at this size, not scaled.</source>
        <translation>A vista é desenhada de novo neste tamanho, sem ser escalada.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose File...</source>
        <translation>Escolher Ficheiro...</translation>
    </message>
</context>
<context>
    <name>lb::FileArguments</name>
    <message>
        <location filename="../../app/window/file_arguments.cpp" line="+52"/>
        <source>Files not opened</source>
        <translation>Ficheiros não abertos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lightbench opens one scene or lesson at a time, the first file given (%1); the files below were not opened. Open them with File &gt; Open Scene or File &gt; Open Lesson.</source>
        <translation>O lightbench abre uma cena ou lição de cada vez, o primeiro ficheiro indicado (%1); os ficheiros abaixo não foram abertos. Abra-os com Ficheiro &gt; Abrir Cena ou Ficheiro &gt; Abrir Lição.</translation>
    </message>
</context>
<context>
    <name>lb::FileLimit</name>
    <message>
        <location filename="../../render/import/import_process.cpp" line="+55"/>
        <source>a texture file</source>
        <translation>um ficheiro de textura</translation>
    </message>
    <message>
        <location line="+129"/>
        <source>a mesh file</source>
        <translation>um ficheiro de malha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the import memory limit</source>
        <translation>o limite de memória da importação</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/lesson.cpp" line="+208"/>
        <location line="+42"/>
        <source>a lesson file</source>
        <translation>um ficheiro de lição</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>the lesson</source>
        <translation>a lição</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/scene_file.cpp" line="+186"/>
        <location line="+15"/>
        <source>a scene file</source>
        <translation>um ficheiro de cena</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>the scene</source>
        <translation>a cena</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/shader_document.cpp" line="+21"/>
        <source>a shader</source>
        <translation>um shader</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/texture_file.cpp" line="+31"/>
        <source>an image</source>
        <translation>uma imagem</translation>
    </message>
    <message>
        <location filename="../../app/window/settings_store.cpp" line="+32"/>
        <location line="+20"/>
        <source>a settings file</source>
        <translation>um ficheiro de definições</translation>
    </message>
</context>
<context>
    <name>lb::FrameLook</name>
    <message>
        <location filename="../../render/model/measure/frame_look.cpp" line="+50"/>
        <source>your program draws nothing: every pixel of the frame is the background (the object is outside the view, or a matrix fed nothing collapses it; the Bindings tab shows what feeds each input)</source>
        <translation>o seu programa não desenha nada: cada píxel da imagem é o fundo (o objeto está fora da vista, ou uma matriz não alimentada colapsa-o; o separador Ligações mostra o que alimenta cada entrada)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>your program draws the object all black: if it is not meant to be, a light or colour input it reads may be fed nothing (the Bindings tab shows what feeds each input)</source>
        <translation>o seu programa desenha o objeto todo preto: se não for essa a intenção, talvez nada alimente uma entrada de luz ou de cor que ele lê (o separador Ligações mostra o que alimenta cada entrada)</translation>
    </message>
</context>
<context>
    <name>lb::Grading</name>
    <message>
        <location filename="../../render/model/grading/grading.cpp" line="+136"/>
        <source>passed</source>
        <extracomment>the outcome of a case, at the end of a grading sheet&apos;s title</extracomment>
        <translation>passou</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>failed</source>
        <translation>falhou</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 - case %2: largest difference %3/255, %4% of %5 pixels within tolerance, %6</source>
        <translation>%1 - caso %2: maior diferença %3/255, %4% de %5 píxeis dentro da tolerância, %6</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 - case %2: largest difference %3/255 at (%4, %5), %6% of %7 pixels within tolerance, %8</source>
        <extracomment>%4, %5: the pixel that differs most</extracomment>
        <translation>%1 - caso %2: maior diferença %3/255 em (%4, %5), %6% de %7 píxeis dentro da tolerância, %8</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>student</source>
        <extracomment>the captions under a grading sheet&apos;s three frames</extracomment>
        <translation>estudante</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>reference</source>
        <translation>referência</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>|student - reference| (white: 64/255)</source>
        <translation>|estudante - referência| (branco: 64/255)</translation>
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
        <translation>%1 ou %2</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Menus</source>
        <extracomment>Help &gt; Keyboard Shortcuts: the heading over every menu&apos;s keys</extracomment>
        <translation>Menus</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Shader editor</source>
        <translation>Editor de shaders</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>compile and link now</source>
        <translation>compilar e ligar (link) agora</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>find in the shader</source>
        <translation>procurar no shader</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>undo / redo (also what a preset, an example or a reset replaced)</source>
        <translation>desfazer / refazer (também o que uma predefinição, um exemplo ou uma reposição substituiu)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>complete the word</source>
        <translation>completar a palavra</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>delete / duplicate the line</source>
        <translation>apagar / duplicar a linha</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>View</source>
        <extracomment>Help &gt; Keyboard Shortcuts: the heading over the mouse and keys of the 3D view (not the View menu)</extracomment>
        <translation>Vista</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>left drag</source>
        <translation>arrastar com o botão esquerdo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>orbit the camera</source>
        <translation>orbitar a câmara</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>click</source>
        <translation>clique</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>select the object under the cursor</source>
        <translation>selecionar o objeto sob o cursor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>right or middle drag</source>
        <translation>arrastar com o botão direito ou do meio</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>pan</source>
        <translation>deslocar a vista</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel</source>
        <translation>roda do rato</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>zoom</source>
        <translation>zoom</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+click, Shift+click</source>
        <extracomment>the keys as the keyboard names them (Ctrl, Shift), held while clicking</extracomment>
        <translation>Ctrl+clique, Shift+clique</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>probe the surface point (drag to move it)</source>
        <translation>sondar o ponto da superfície (arraste para o mover)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drag the wipe&apos;s line</source>
        <translation>arrastar a linha da cortina</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>move the wipe (compare)</source>
        <translation>mover a cortina (comparação)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>drop a file</source>
        <translation>largar um ficheiro</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>open a mesh, a scene, a lesson or a shader pair</source>
        <translation>abrir uma malha, uma cena, uma lição ou um par de shaders</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Keyboard shortcuts - lightbench</source>
        <translation>Atalhos de teclado - lightbench</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Features - lightbench</source>
        <translation>Funcionalidades - lightbench</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The README is missing from this build.</source>
        <translation>O README não está incluído nesta compilação.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>About lightbench</source>
        <translation>Acerca do lightbench</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;lightbench %1&lt;/h3&gt;&lt;p&gt;A workbench for the lighting model of computer graphics courses: ambient, diffuse and specular terms, Phong and Blinn-Phong, Gouraud and Phong shading, every pixel checked against a CPU reference.&lt;/p&gt;&lt;p&gt;Qt %2 (built with %3)&lt;br&gt;%4&lt;/p&gt;</source>
        <translation>&lt;h3&gt;lightbench %1&lt;/h3&gt;&lt;p&gt;Uma bancada de trabalho para o modelo de iluminação das disciplinas de computação gráfica: termos ambiente, difuso e especular, Phong e Blinn-Phong, sombreamento de Gouraud e de Phong, com cada píxel verificado face a uma referência calculada no CPU.&lt;/p&gt;&lt;p&gt;Qt %2 (compilado com %3)&lt;br&gt;%4&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>OpenGL not started yet</source>
        <translation>O OpenGL ainda não foi iniciado</translation>
    </message>
</context>
<context>
    <name>lb::ImageTruncation</name>
    <message>
        <location filename="../../render/model/io/image_truncation.cpp" line="+33"/>
        <source>no image data (no scan)</source>
        <translation>sem dados de imagem (nenhum scan)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file ends inside the image data (no end-of-image marker): cut short?</source>
        <translation>o ficheiro termina a meio dos dados da imagem (sem marcador de fim de imagem): truncado?</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the file ends inside its header</source>
        <translation>o ficheiro termina a meio do cabeçalho</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the file ends inside the image data (%1 of %2 bytes): cut short?</source>
        <translation>o ficheiro termina a meio dos dados da imagem (%1 de %2 bytes): truncado?</translation>
    </message>
</context>
<context>
    <name>lb::ImportProcess</name>
    <message>
        <location filename="../../render/import/import_process.cpp" line="-156"/>
        <source>the importer crashed with a segmentation fault while reading this file; the workbench is fine</source>
        <translation>o importador terminou abruptamente com uma falha de segmentação ao ler este ficheiro; a bancada de trabalho não foi afetada</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the importer crashed with an abort while reading this file; the workbench is fine</source>
        <translation>o importador terminou abruptamente com um abort ao ler este ficheiro; a bancada de trabalho não foi afetada</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with a bus error while reading this file; the workbench is fine</source>
        <translation>o importador terminou abruptamente com um erro de barramento (bus error) ao ler este ficheiro; a bancada de trabalho não foi afetada</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with an arithmetic error while reading this file; the workbench is fine</source>
        <translation>o importador terminou abruptamente com um erro aritmético ao ler este ficheiro; a bancada de trabalho não foi afetada</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the importer crashed with an illegal instruction while reading this file; the workbench is fine</source>
        <translation>o importador terminou abruptamente com uma instrução ilegal ao ler este ficheiro; a bancada de trabalho não foi afetada</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the importer crashed with signal %1 (%2) while reading this file; the workbench is fine</source>
        <extracomment>%1 a signal&apos;s number, %2 the system&apos;s name for it</extracomment>
        <translation>o importador terminou abruptamente com o sinal %1 (%2) ao ler este ficheiro; a bancada de trabalho não foi afetada</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>texture &apos;%1&apos;: outside the mesh&apos;s folder</source>
        <translation>textura &apos;%1&apos;: fora da pasta da malha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>texture &apos;%1&apos; not found</source>
        <translation>textura &apos;%1&apos; não encontrada</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1: cannot start the import helper &apos;%2&apos;: %3</source>
        <translation>%1: não é possível iniciar o processo auxiliar de importação &apos;%2&apos;: %3</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1: not readable (permissions)</source>
        <translation>%1: não pode ser lido (permissões)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the file is empty</source>
        <translation>%1: o ficheiro está vazio</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1: cancelled</source>
        <translation>%1: cancelado</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: gave up after %2 s (the import time limit)</source>
        <translation>%1: abandonado após %2 s (o limite de tempo da importação)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>gave up after %1 s of CPU time (the import time limit)</source>
        <translation>abandonado após %1 s de tempo de CPU (o limite de tempo da importação)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import helper was killed (by the system, for memory?)</source>
        <translation>o processo auxiliar de importação foi terminado à força (pelo sistema, por falta de memória?)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of memory: reading this file needs more than the import memory limit (%1 MB)</source>
        <translation>sem memória: ler este ficheiro exige mais do que o limite de memória da importação (%1 MB)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the import helper stopped (exit code %1) before sending the whole mesh</source>
        <translation>o processo auxiliar de importação parou (código de saída %1) antes de enviar a malha completa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import helper stopped (exit code %1) before sending the whole mesh: %2</source>
        <extracomment>%2 the last line the helper wrote on its error output (its own words, in English)</extracomment>
        <translation>o processo auxiliar de importação parou (código de saída %1) antes de enviar a malha completa: %2</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>embedded texture unreadable: %1</source>
        <translation>textura incorporada ilegível: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>texture %1</source>
        <extracomment>%1 why a texture file cannot be used, &quot;PATH: reason&quot;</extracomment>
        <translation>textura %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>texture &apos;%1&apos;: %2</source>
        <translation>textura &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file has a texture but no texture coordinates</source>
        <translation>o ficheiro tem uma textura mas não tem coordenadas de textura</translation>
    </message>
</context>
<context>
    <name>lb::Language</name>
    <message>
        <location filename="../../app/common/language.cpp" line="+48"/>
        <source>&amp;System</source>
        <extracomment>View &gt; Language: follow the system&apos;s language (LANG)</extracomment>
        <translation>&amp;Sistema</translation>
    </message>
    <message>
        <location filename="../../app/window/language_menu.cpp" line="+21"/>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../../app/window/run_window.cpp" line="+142"/>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The window changes its language when lightbench starts again. Restart now?</source>
        <translation>A janela muda de idioma quando o lightbench voltar a arrancar. Reiniciar agora?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lightbench closes as it does on Quit, asking about unsaved work, and opens again where you were.</source>
        <translation>O lightbench fecha como em Sair, perguntando pelo trabalho não guardado, e volta a abrir onde estava.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Restart &amp;Now</source>
        <translation>Reiniciar &amp;Agora</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Later</source>
        <translation>&amp;Mais Tarde</translation>
    </message>
    <message>
        <location filename="../../app/window/run_window.cpp" line="+1"/>
        <source>lightbench could not start again. Start it yourself to see the new language.</source>
        <translation>O lightbench não conseguiu voltar a arrancar. Inicie-o para ver o novo idioma.</translation>
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
        <translation>&quot;%1&quot; não é nenhum destes: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a value that is not text is not one of %1</source>
        <translation>um valor que não é texto não é nenhum destes: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>%1: the scene file %2 (%3) is past what is left of the lesson&apos;s limit (%4 for the lesson and its scene files)</source>
        <extracomment>%1 the step (&quot;step 3&quot;), %2 a path, %3 its size, %4 the limit</extracomment>
        <translation>%1: o ficheiro de cena %2 (%3) excede o que resta do limite da lição (%4 para a lição e os seus ficheiros de cena)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: no scene (&quot;scene&quot; must be a scene object or the name of a scene file)</source>
        <translation>%1: sem cena (&quot;scene&quot; tem de ser um objeto de cena ou o nome de um ficheiro de cena)</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>%1: not a lesson file: %2 at byte %3</source>
        <extracomment>%1 a path, %2 Qt&apos;s JSON parser&apos;s reason</extracomment>
        <translation>%1: não é um ficheiro de lição: %2 no byte %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: a scene file, not a lesson (open it with File &gt; Open Scene)</source>
        <translation>%1: é um ficheiro de cena, não uma lição (abra-o com Ficheiro &gt; Abrir Cena)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: not a lesson file (&quot;format&quot; is not &quot;%2&quot;)</source>
        <translation>%1: não é um ficheiro de lição (&quot;format&quot; não é &quot;%2&quot;)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>missing or not a number; read as %1</source>
        <translation>em falta ou não é um número; lido como %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>newer than this lightbench&apos;s %1: what it does not know is left out</source>
        <translation>mais recente do que a versão %1 deste lightbench: o que este não conhece fica de fora</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the lesson has no steps (&quot;steps&quot; must be a list of steps)</source>
        <translation>%1: a lição não tem passos (&quot;steps&quot; tem de ser uma lista de passos)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 steps; a lesson may have at most %3</source>
        <translation>%1: %2 passos; uma lição pode ter no máximo %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>step %1</source>
        <extracomment>where in a lesson file a message is about: &quot;step 3: title (not text)&quot;</extracomment>
        <translation>passo %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: not an object</source>
        <translation>%1: não é um objeto</translation>
    </message>
</context>
<context>
    <name>lb::LessonActions</name>
    <message>
        <location filename="../../app/window/lesson_actions.cpp" line="+43"/>
        <source>Open Recent &amp;Lesson</source>
        <translation>Abrir Lição Recen&amp;te</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The last lesson could not be opened again: %1</source>
        <translation>Não foi possível voltar a abrir a última lição: %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Open &amp;Lesson...</source>
        <translation>Abrir &amp;Lição...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lesso&amp;ns</source>
        <translation>Liçõ&amp;es</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>(none built in)</source>
        <translation>(nenhuma incluída)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Less&amp;on</source>
        <translation>&amp;Lição</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Next Step</source>
        <translation>Passo &amp;Seguinte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Previous Step</source>
        <translation>Passo &amp;Anterior</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;First Step</source>
        <translation>&amp;Primeiro Passo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Last Step</source>
        <translation>Ú&amp;ltimo Passo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset Step</source>
        <translation>&amp;Repor Passo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New Lesson from This &amp;View</source>
        <translation>&amp;Nova Lição a Partir Desta Vista</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Add This View as a Step</source>
        <translation>A&amp;dicionar Esta Vista como Passo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace the Step with &amp;This View</source>
        <translation>Substituir o Passo por Es&amp;ta Vista</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rena&amp;me Step...</source>
        <translation>&amp;Mudar o Nome do Passo...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit &amp;Caption...</source>
        <translation>&amp;Editar Legenda...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move Step &amp;Up</source>
        <translation>Mover Passo para &amp;Cima</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move Step &amp;Down</source>
        <translation>Mover Passo para &amp;Baixo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remo&amp;ve Step</source>
        <translation>Remo&amp;ver Passo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save Lesson</source>
        <translation>&amp;Guardar Lição</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Lesson &amp;As...</source>
        <translation>Guardar Lição C&amp;omo...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Close Lesson</source>
        <translation>&amp;Fechar Lição</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Caption &amp;Language</source>
        <translation>&amp;Idioma da Legenda</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Same as the Window</source>
        <extracomment>Lesson &gt; Caption Language: the same language as the window&apos;s menus (View &gt; Language)</extracomment>
        <translation>Idioma da Janela</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>untitled lesson</source>
        <translation>lição sem título</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The lesson could not be opened; nothing changed.</source>
        <translation>Não foi possível abrir a lição; nada mudou.</translation>
    </message>
    <message numerus="yes">
        <location line="+22"/>
        <source>%1 opened; %n step(s) cannot be shown (the lesson bar says why there).</source>
        <translation>
            <numerusform>Abriu-se %1; %n passo não pode ser mostrado (a barra da lição diz porquê, nesse passo).</numerusform>
            <numerusform>Abriu-se %1; %n passos não podem ser mostrados (a barra da lição diz porquê, nesses passos).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%1 opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>Abriu-se %1; %n campo não pôde ser usado e ficou com o valor predefinido.</numerusform>
            <numerusform>Abriu-se %1; %n campos não puderam ser usados e ficaram com os valores predefinidos.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+115"/>
        <location filename="../../app/window/lesson_authoring.cpp" line="+35"/>
        <location line="+34"/>
        <source>Step %1</source>
        <extracomment>a new step&apos;s title, until the teacher renames it (saved in the lesson file)</extracomment>
        <translation>Passo %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Open a lesson</source>
        <translation>Abrir uma lição</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lessons (*.lblesson *.json);;All files (*)</source>
        <translation>Lições (*.lblesson *.json);;Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+9"/>
        <location filename="../../app/window/lesson_authoring.cpp" line="-37"/>
        <source>Lesson</source>
        <extracomment>a new lesson&apos;s title, until the teacher renames it (saved in the lesson file)</extracomment>
        <translation>Lição</translation>
    </message>
    <message>
        <location filename="../../app/window/lesson_authoring.cpp" line="+26"/>
        <source>A lesson has at most %1 steps and this one has them all: the view was not added</source>
        <translation>Uma lição tem no máximo %1 passos e esta já os tem todos: a vista não foi acrescentada</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>The step keeps its title.</source>
        <translation>O passo mantém o seu título.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A step&apos;s title cannot be empty.</source>
        <translation>O título de um passo não pode estar vazio.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The title has %1 characters; a title holds at most %2.</source>
        <translation>O título tem %1 carateres; um título tem no máximo %2.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The step keeps its caption.</source>
        <translation>O passo mantém a sua legenda.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 caption has %2 characters; a caption holds at most %3.</source>
        <extracomment>%1: the caption&apos;s language code (en, de, pt)</extracomment>
        <translation>A legenda (%1) tem %2 carateres; uma legenda tem no máximo %3.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>The step stays.</source>
        <translation>O passo mantém-se.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A lesson keeps at least one step; Close Lesson puts it away.</source>
        <translation>Uma lição tem pelo menos um passo; Fechar Lição arruma-a.</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>The lesson was not saved; it stays open with its changes.</source>
        <translation>A lição não foi guardada; continua aberta com as suas alterações.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved the lesson to %1</source>
        <translation>Lição guardada em %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Lessons (*.json)</source>
        <translation>Lições (*.json)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lightbench lessons (*.lblesson)</source>
        <translation>Lições do lightbench (*.lblesson)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the lesson</source>
        <translation>Guardar a lição</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation>Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Rename Step</source>
        <translation>Mudar o Nome do Passo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The title of step %1:</source>
        <translation>O título do passo %1:</translation>
    </message>
</context>
<context>
    <name>lb::LessonBar</name>
    <message>
        <location filename="../../widgets/lesson_bar.cpp" line="+44"/>
        <source>The previous step (PageUp, Left)</source>
        <translation>O passo anterior (Page Up, Seta Esquerda)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The next step (PageDown, Right, Space)</source>
        <translation>O passo seguinte (Page Down, Seta Direita, Espaço)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reset Step</source>
        <translation>Repor Passo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This step as the lesson has it: your changes to it are set aside</source>
        <translation>Este passo tal como a lição o tem: as suas alterações a ele são postas de lado</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The Lesson menu: add, rename, caption, move and save steps</source>
        <translation>O menu Lição: adicionar, mudar o nome, legendar, mover e guardar passos</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Close the lesson (the scene stays)</source>
        <translation>Fechar a lição (a cena mantém-se)</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Step %1 of %2</source>
        <extracomment>where the class is in the lesson: step %1 of %2 steps</extracomment>
        <translation>Passo %1 de %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>This step cannot be shown; the scene is as it was. %1</source>
        <translation>Este passo não pode ser mostrado; a cena está como estava. %1</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>[picture]</source>
        <extracomment>in a lesson&apos;s caption, where the markdown had an image (never shown there)</extracomment>
        <translation>[imagem]</translation>
    </message>
</context>
<context>
    <name>lb::LightPanel</name>
    <message>
        <location filename="../../widgets/light_panel.cpp" line="+40"/>
        <location line="+172"/>
        <source>Light %1</source>
        <translation>Luz %1</translation>
    </message>
    <message>
        <location line="-169"/>
        <source>Up to four lights; their terms add up. A shader that declares one light (not an array) reads light 1</source>
        <translation>Até quatro luzes; os seus termos somam-se. Um shader que declara uma só luz (não um array) lê a luz 1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>On</source>
        <extracomment>the light is switched on (a check box)</extracomment>
        <translation>Ligada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uLightEnabled[i]: a light switched off adds nothing (its colours go to shaders as black)</source>
        <translation>uLightEnabled[i]: uma luz desligada não contribui nada (as suas cores chegam aos shaders como preto)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Light</source>
        <extracomment>the row of the light&apos;s on/off switch</extracomment>
        <translation>Luz</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Position</source>
        <translation>Posição</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>w = 1: point light</source>
        <extracomment>w is the light position&apos;s 4th (homogeneous) coordinate: a symbol, not a word</extracomment>
        <translation>w = 1: luz pontual</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>w = 0: directional</source>
        <translation>w = 0: direcional</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lightPosition.w: 1 puts the light at (x, y, z); 0 makes (x, y, z) the direction towards a light at infinity</source>
        <translation>lightPosition.w: 1 coloca a luz em (x, y, z); 0 faz de (x, y, z) a direção para uma luz no infinito</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Type</source>
        <extracomment>a light&apos;s type: point or directional</extracomment>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Camera: moves with the eye</source>
        <translation>Câmara: move-se com o olho</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>World: fixed in the scene</source>
        <translation>Mundo: fixa na cena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Object: turns with the model</source>
        <translation>Objeto: roda com o modelo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame lightPosition is given in. Camera: used as is (variant I); world: mView / mViewNormals (II); object: mModelView / mNormals (III)</source>
        <translation>Referencial em que lightPosition é dada. Câmara: usada tal como está (variante I); mundo: mView / mViewNormals (II); objeto: mModelView / mNormals (III)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The object whose frame an object-frame light is given in: the light turns and moves with it, and lights every object from there</source>
        <translation>O objeto em cujo referencial é dada uma luz no referencial do objeto: a luz roda e move-se com ele, e ilumina todos os objetos a partir daí</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Frame</source>
        <extracomment>the coordinate frame the light&apos;s position is given in</extracomment>
        <translation>Referencial</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Of object</source>
        <extracomment>the object whose frame an object-frame light is given in</extracomment>
        <translation>Do objeto</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Atten. kc kl kq</source>
        <translation>Aten. kc kl kq</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Spot axis</source>
        <translation>Eixo do foco</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Spot cutoff, exp</source>
        <extracomment>the spotlight&apos;s cutoff angle and exponent</extracomment>
        <translation>Corte do foco, exp</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset light</source>
        <translation>Repor luz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This light&apos;s defaults; light 1&apos;s are the slides&apos; (0, 1.8, 1.3, 1) in world coordinates</source>
        <translation>Os valores predefinidos desta luz; os da luz 1 são os dos diapositivos, (0, 1.8, 1.3, 1) em coordenadas do mundo</translation>
    </message>
</context>
<context>
    <name>lb::LightingParameters</name>
    <message>
        <location filename="../../render/model/lighting/lighting_parameters.cpp" line="+16"/>
        <source>w must be 0 (directional) or 1 (point)</source>
        <translation>w tem de ser 0 (direcional) ou 1 (pontual)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a directional light (w = 0) with the direction 0, 0, 0</source>
        <translation>uma luz direcional (w = 0) com a direção 0, 0, 0</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>kc, kl and kq all 0 (the light would be infinite)</source>
        <translation>kc, kl e kq todos a 0 (a luz seria infinita)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a direction of length 0</source>
        <translation>uma direção de comprimento 0</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>lightPosition.%1: the light&apos;s %1 in the chosen frame</source>
        <translation>lightPosition.%1: a coordenada %1 da luz no referencial escolhido</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 (%2): the light&apos;s ambient intensity</source>
        <extracomment>%1 the symbol (Ia, Id, Is); %2 the uniforms that carry it</extracomment>
        <translation>%1 (%2): a intensidade ambiente da luz</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (%2): the light&apos;s diffuse intensity</source>
        <translation>%1 (%2): a intensidade difusa da luz</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (%2): the light&apos;s specular intensity</source>
        <translation>%1 (%2): a intensidade especular da luz</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>lightAttenuation.%1 (%2): a point light&apos;s terms are divided by kc + kl·d + kq·d², d its distance to the surface (1, 0, 0: none; a directional light is never attenuated)</source>
        <extracomment>%1 the axis (x, y, z); %2 its name (kc, kl, kq)</extracomment>
        <translation>lightAttenuation.%1 (%2): os termos de uma luz pontual são divididos por kc + kl·d + kq·d², sendo d a sua distância à superfície (1, 0, 0: nenhuma; uma luz direcional nunca é atenuada)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>spotDirection.%1: the spotlight&apos;s axis, from the light, in the light&apos;s frame</source>
        <translation>spotDirection.%1: o eixo do holofote, a partir da luz, no referencial da luz</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>spotCutoff: the cone&apos;s half-angle; outside it the light adds nothing, ambient included (180: no spot)</source>
        <translation>spotCutoff: o semiângulo do cone; fora dele a luz não contribui nada, incluindo o termo ambiente (180: sem foco)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>spotExponent: inside the cone the terms are scaled by max(-L·D, 0)^exponent, brighter towards the axis</source>
        <translation>spotExponent: dentro do cone os termos são multiplicados por max(-L·D, 0)^exponent, mais brilhantes perto do eixo</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (%2): the material&apos;s ambient reflection coefficients</source>
        <extracomment>%1 the symbol (Ka, Kd, Ks); %2 the uniforms that carry it</extracomment>
        <translation>%1 (%2): os coeficientes de reflexão ambiente do material</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 (%2): the material&apos;s diffuse reflection coefficients</source>
        <translation>%1 (%2): os coeficientes de reflexão difusa do material</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 (%2): the material&apos;s specular reflection coefficients</source>
        <translation>%1 (%2): os coeficientes de reflexão especular do material</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>shininess: the specular exponent n in (R.V)^n or (N.H)^n; higher gives a smaller, sharper highlight</source>
        <translation>shininess: o expoente especular n em (R.V)^n ou (N.H)^n; maior dá um reflexo especular menor e mais nítido</translation>
    </message>
</context>
<context>
    <name>lb::LoadProgress</name>
    <message>
        <location filename="../../widgets/load_progress.cpp" line="+21"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop loading: the import helper is stopped, the current mesh stays</source>
        <translation>Parar o carregamento: o processo auxiliar de importação é parado e a malha atual mantém-se</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Loading %1...</source>
        <translation>A carregar %1...</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Loading %1: %2</source>
        <translation>A carregar %1: %2</translation>
    </message>
</context>
<context>
    <name>lb::LocalizedText</name>
    <message>
        <location filename="../../render/model/scene/localized_text.cpp" line="+29"/>
        <source>not text</source>
        <translation>não é texto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 characters; at most %2</source>
        <translation>%1 carateres; no máximo %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not a language code</source>
        <translation>não é um código de idioma</translation>
    </message>
</context>
<context>
    <name>lb::Loops</name>
    <message>
        <location filename="../../render/glsl/loop_messages.cpp" line="+18"/>
        <source>this loop runs %1 times for every fragment: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>este ciclo é executado %1 vezes por cada fragmento: um fotograma demoraria segundos ou mais em qualquer GPU (o llvmpipe interrompe-o ao fim de 65 535 iterações e desenha uma imagem errada)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this loop runs %1 times for every fragment (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>este ciclo é executado %1 vezes por cada fragmento (o seu contador afasta-se do limite: só termina quando o contador dá a volta): um fotograma demoraria segundos ou mais em qualquer GPU (o llvmpipe interrompe-o ao fim de 65 535 iterações e desenha uma imagem errada)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this loop runs %1 times for every vertex: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>este ciclo é executado %1 vezes por cada vértice: um fotograma demoraria segundos ou mais em qualquer GPU (o llvmpipe interrompe-o ao fim de 65 535 iterações e desenha uma imagem errada)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this loop runs %1 times for every vertex (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>este ciclo é executado %1 vezes por cada vértice (o seu contador afasta-se do limite: só termina quando o contador dá a volta): um fotograma demoraria segundos ou mais em qualquer GPU (o llvmpipe interrompe-o ao fim de 65 535 iterações e desenha uma imagem errada)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every fragment: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>este programa nunca termina um fotograma: o ciclo aqui é executado %1 vezes por cada fragmento: um fotograma demoraria segundos ou mais em qualquer GPU (o llvmpipe interrompe-o ao fim de 65 535 iterações e desenha uma imagem errada)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every fragment (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>este programa nunca termina um fotograma: o ciclo aqui é executado %1 vezes por cada fragmento (o seu contador afasta-se do limite: só termina quando o contador dá a volta): um fotograma demoraria segundos ou mais em qualquer GPU (o llvmpipe interrompe-o ao fim de 65 535 iterações e desenha uma imagem errada)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every vertex: a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>este programa nunca termina um fotograma: o ciclo aqui é executado %1 vezes por cada vértice: um fotograma demoraria segundos ou mais em qualquer GPU (o llvmpipe interrompe-o ao fim de 65 535 iterações e desenha uma imagem errada)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>this program never finishes a frame: the loop here runs %1 times for every vertex (its counter moves away from its bound: only wrapping around ends it): a frame would take seconds or more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong picture)</source>
        <translation>este programa nunca termina um fotograma: o ciclo aqui é executado %1 vezes por cada vértice (o seu contador afasta-se do limite: só termina quando o contador dá a volta): um fotograma demoraria segundos ou mais em qualquer GPU (o llvmpipe interrompe-o ao fim de 65 535 iterações e desenha uma imagem errada)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>this loop never ends: it has no condition and nothing in it breaks, returns or discards (the driver may drop it and draw garbage, or hang)</source>
        <translation>este ciclo nunca termina: não tem condição e nada nele faz break, return ou discard (o controlador pode descartá-lo e desenhar lixo, ou bloquear)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this loop never ends: its condition is always true and nothing in it breaks, returns or discards (the driver may drop it and draw garbage, or hang)</source>
        <translation>este ciclo nunca termina: a sua condição é sempre verdadeira e nada nele faz break, return ou discard (o controlador pode descartá-lo e desenhar lixo, ou bloquear)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this program never finishes a frame: the loop here has no condition (or an always-true one) and no break, return or discard</source>
        <translation>este programa nunca termina um fotograma: o ciclo aqui não tem condição (ou tem uma sempre verdadeira) nem break, return ou discard</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>this loop never ends once it starts: its condition reads %1, and nothing in the loop changes it</source>
        <extracomment>%1 the names the loop&apos;s condition reads, as the shader spells them (&quot;i, n&quot;)</extracomment>
        <translation>este ciclo, uma vez iniciado, nunca termina: a sua condição lê %1, e nada no ciclo altera essa variável</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this loop never ends once it starts: its condition reads %1, and nothing in the loop changes them</source>
        <translation>este ciclo, uma vez iniciado, nunca termina: a sua condição lê %1, e nada no ciclo altera essas variáveis</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 (the loop comes from macro %2, used on this line)</source>
        <extracomment>%1 a message about a loop, %2 the name of the macro that writes the loop</extracomment>
        <translation>%1 (o ciclo vem da macro %2, usada nesta linha)</translation>
    </message>
</context>
<context>
    <name>lb::MacroExpansion</name>
    <message>
        <location filename="../../render/glsl/macro_expansion.cpp" line="+94"/>
        <source>macro %1 expands through more than %2 macros, one inside another: refused before the driver sees it</source>
        <translation>a macro %1 expande-se através de mais de %2 macros, umas dentro das outras: recusada antes de chegar ao controlador</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>macro %1 expands to more than a million tokens (a macro that doubles itself?): refused before the driver sees it</source>
        <translation>a macro %1 expande-se em mais de um milhão de tokens (uma macro que se duplica a si própria?): recusada antes de chegar ao controlador</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>macro %1 expands to more than 1 MB of text (a macro that doubles itself?): refused before the driver sees it</source>
        <translation>a macro %1 expande-se em mais de 1 MB de texto (uma macro que se duplica a si própria?): recusada antes de chegar ao controlador</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>macro %1 calls macros inside macro arguments more than %2 deep: refused before the driver sees it</source>
        <translation>a macro %1 chama macros dentro de argumentos de macros com mais de %2 níveis de profundidade: recusada antes de chegar ao controlador</translation>
    </message>
</context>
<context>
    <name>lb::MainWindow</name>
    <message>
        <location filename="../../app/window/main_window.cpp" line="+85"/>
        <source>Light</source>
        <translation>Luz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shading</source>
        <translation>Sombreamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Object</source>
        <translation>Objeto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Uniforms</source>
        <translation>Uniformes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bindings</source>
        <translation>Ligações</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Probe</source>
        <translation>Sonda</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Plots</source>
        <translation>Gráficos</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exercise</source>
        <translation>Exercício</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Shader editor</source>
        <translation>Editor de shaders</translation>
    </message>
    <message>
        <location line="+40"/>
        <location filename="../../app/window/main_window_menus.cpp" line="+53"/>
        <location filename="../../app/window/main_window_unsaved.cpp" line="+92"/>
        <location line="+13"/>
        <source>Shader files</source>
        <translation>Ficheiros de shader</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Unsaved shader edits from the last session are back</source>
        <translation>As edições dos shaders por guardar da última sessão foram recuperadas</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Everything reset; Ctrl+Z in the editor brings your shader text back</source>
        <translation>Tudo reposto; Ctrl+Z no editor recupera o texto do seu shader</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Everything reset</source>
        <translation>Tudo reposto</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The program on screen computes V = (0,0,1), the parallel view vector, under the perspective projection; the reference uses V = -P, so the two differ away from the middle of the view. The orthographic projection (key P) makes them agree.</source>
        <translation>O programa no ecrã calcula V = (0,0,1), o vetor de observação da projeção paralela, sob a projeção perspetiva; a referência usa V = -P, pelo que os dois diferem longe do centro da vista. A projeção ortográfica (tecla P) põe-nos de acordo.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 shades as it is written: Gouraud/Phong does not change it. A preset or Reset Everything brings the built-in program, which follows this choice.</source>
        <translation>%1 sombreia tal como está escrito: Gouraud/Phong não o altera. Uma predefinição ou Repor Tudo traz o programa integrado, que segue esta escolha.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The program in the editor (%1) shades Gouraud (per vertex) whatever this says. Load a preset or Reset Everything to switch shading.</source>
        <translation>O programa no editor (%1) usa sombreamento de Gouraud (por vértice), seja qual for a escolha aqui. Carregue uma predefinição ou use Repor Tudo para mudar o sombreamento.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The program in the editor (%1) shades Phong (per fragment) whatever this says. Load a preset or Reset Everything to switch shading.</source>
        <translation>O programa no editor (%1) usa sombreamento de Phong (por fragmento), seja qual for a escolha aqui. Carregue uma predefinição ou use Repor Tudo para mudar o sombreamento.</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1, step %2</source>
        <translation>%1, passo %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>untitled</source>
        <translation>sem título</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1[*] - lightbench</source>
        <translation>%1[*] - lightbench</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_budget.cpp" line="+44"/>
        <source>More would take more memory than the scene&apos;s meshes may take on this machine: %1 for all objects together.</source>
        <translation>Mais do que isto exigiria mais memória do que as malhas da cena podem ocupar nesta máquina: %1 para todos os objetos juntos.</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_exercise.cpp" line="+72"/>
        <source>Check cancelled.</source>
        <translation>Verificação cancelada.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Checked: %1 of %2 cases pass</source>
        <translation>Verificado: %1 de %2 casos passam</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>Not checked: %1</source>
        <extracomment>a check that graded nothing, for a reason this version does not know (%1, in English)</extracomment>
        <translation>Não verificado: %1</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>Side B</source>
        <translation>Lado B</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not checked: does not compile</source>
        <translation>Não verificado: o programa não compila</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: does not link</source>
        <translation>Não verificado: a ligação (link) falhou</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: refused</source>
        <translation>Não verificado: programa recusado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: timed out</source>
        <translation>Não verificado: tempo esgotado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: could not start</source>
        <translation>Não verificado: não foi possível iniciar a verificação</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: crashed</source>
        <translation>Não verificado: a verificação terminou abruptamente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not checked: unreadable</source>
        <translation>Não verificado: programa ilegível</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+2"/>
        <source>Not checked: the exercise has a broken mistake</source>
        <translation>Não verificado: o exercício tem um erro conhecido que não funciona</translation>
    </message>
    <message>
        <location line="+83"/>
        <location line="+16"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>the exercise&apos;s reference</source>
        <translation>a referência do exercício</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>the exercise&apos;s reference (built-in)</source>
        <translation>a referência do exercício (integrada)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+39"/>
        <source>the built-in program</source>
        <translation>o programa integrado</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>side B (%1)</source>
        <translation>lado B (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Side B draws %1: it shades as it is written, so these choices do nothing. The x button brings back %2.</source>
        <translation>O lado B desenha %1: sombreia tal como está escrito, por isso estas escolhas não fazem nada. O botão x traz de volta %2.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Side B draws the exercise&apos;s reference program: it shades as it is written, so these choices do nothing.</source>
        <translation>O lado B desenha o programa de referência do exercício: sombreia tal como está escrito, por isso estas escolhas não fazem nada.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the exercise&apos;s reference (built-in, %1 shading, %2 specular)</source>
        <extracomment>%1: gouraud, phong or flat; %2: phong or blinn</extracomment>
        <translation>a referência do exercício (integrada, sombreamento %1, especular %2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the built-in program, %1 shading and %2 specular (the exercise&apos;s reference)</source>
        <extracomment>%1: gouraud, phong or flat; %2: phong or blinn</extracomment>
        <translation>o programa integrado, sombreamento %1 e especular %2 (a referência do exercício)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The exercise&apos;s reference fixes side B&apos;s choices.</source>
        <translation>A referência do exercício fixa as escolhas do lado B.</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Side B is unchanged: %1</source>
        <translation>O lado B não mudou: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Side B is unchanged: %1 does not build:
%2</source>
        <translation>O lado B não mudou: %1 não pode ser construído:
%2</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Side B: a shader pair (NAME.vert or NAME.frag) or a scene file&apos;s program</source>
        <translation>Lado B: um par de shaders (NAME.vert ou NAME.frag) ou o programa de um ficheiro de cena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shader pairs and scene files (*.vert *.frag *.json *.lbscene);;All files (*)</source>
        <translation>Pares de shaders e ficheiros de cena (*.vert *.frag *.json *.lbscene);;Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The check could not start: %1</source>
        <translation>Não foi possível iniciar a verificação: %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Case %1 in the difference view (key C: the other compare views; &quot;Back to my scene&quot; in the Exercise panel)</source>
        <extracomment>&quot;Back to my scene&quot; is the Exercise panel&apos;s button: its name as translated there</extracomment>
        <translation>Caso %1 na vista de diferença (tecla C: as outras vistas de comparação; &quot;Voltar à minha cena&quot; no painel Exercício)</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_menus.cpp" line="-13"/>
        <source>&amp;File</source>
        <translation>&amp;Ficheiro</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Chec&amp;k My Work</source>
        <translation>&amp;Verificar o Meu Trabalho</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>F9</source>
        <translation>F9</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Side B: Shader Files...</source>
        <translation>Lado B: Ficheiros de Shader...</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../../app/window/main_window_unsaved.cpp" line="-5"/>
        <source>Shader pairs (*.vert *.frag);;All files (*)</source>
        <translation>Pares de shaders (*.vert *.frag);;Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open S&amp;haders...</source>
        <translation>Abrir S&amp;haders...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a shader pair (NAME.vert and NAME.frag)</source>
        <translation>Abrir um par de shaders (NAME.vert e NAME.frag)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save Shaders</source>
        <translation>Guardar Shaders</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Alt+S</source>
        <translation>Ctrl+Alt+S</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Shaders As...</source>
        <translation>Guardar Shaders Como...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <extracomment>the menu (camera, probe, zoom, presentation, docks), not the 3D view itself</extracomment>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reset &amp;Everything</source>
        <translation>Repor T&amp;udo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+R</source>
        <translation>Ctrl+Shift+R</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>&amp;Sair</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Undo in the Editor</source>
        <translation>&amp;Desfazer no Editor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Redo in the Editor</source>
        <translation>&amp;Refazer no Editor</translation>
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
        <translation>&amp;Procurar no Shader</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Shading</source>
        <translation>&amp;Sombreamento</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Toggle &amp;Gouraud / Phong</source>
        <translation>Alternar &amp;Gouraud / Phong</translation>
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
        <translation>Alternar Especular Phong / &amp;Blinn-Phong</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+B</source>
        <translation>Ctrl+B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The program in the editor (%1) computes its own specular term: load a preset or Reset Everything to switch it.</source>
        <translation>O programa no editor (%1) calcula o seu próprio termo especular: carregue uma predefinição ou use Repor Tudo para o mudar.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Toggle &amp;Perspective / Orthographic</source>
        <translation>Alternar Projeção &amp;Perspetiva / Ortográfica</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Toggle &amp;Lighting</source>
        <translation>Alternar &amp;Iluminação</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Toggle the &amp;Ambient Term</source>
        <translation>Alternar o Termo &amp;Ambiente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toggle the &amp;Diffuse Term</source>
        <translation>Alternar o Termo &amp;Difuso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toggle the &amp;Specular Term</source>
        <translation>Alternar o Termo &amp;Especular</translation>
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
        <translation>&amp;Comparação: Desligada / Lado a Lado / Cortina / Diferença</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Reset Camera</source>
        <translation>&amp;Repor a Câmara</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clear the &amp;Probe (in Presentation Mode: Leave It)</source>
        <translation>Limpar a &amp;Sonda (no Modo de Apresentação: Sair Dele)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Esc</source>
        <translation>Esc</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Auto-rotate</source>
        <translation>Rodar &amp;Automaticamente</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Space</source>
        <translation>Space</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Help</source>
        <translation>A&amp;juda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Atalhos de Teclado</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Features (README)</source>
        <translation>&amp;Funcionalidades (README)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About lightbench</source>
        <translation>A&amp;cerca do lightbench</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Zoom &amp;In Editor</source>
        <translation>Amp&amp;liar o Editor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+=</source>
        <translation>Ctrl+=</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom &amp;Out Editor</source>
        <translation>Red&amp;uzir o Editor</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reset Editor &amp;Zoom</source>
        <translation>Repor o &amp;Zoom do Editor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>UI &amp;Scale</source>
        <translation>Escala da &amp;Interface</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1%</source>
        <extracomment>View &gt; UI Scale: a size in percent (&quot;125%&quot;)</extracomment>
        <translation>%1%</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Fit the &amp;Window to the Screen</source>
        <translation>Ajustar a &amp;Janela ao Ecrã</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_presentation.cpp" line="+54"/>
        <source>&amp;Presentation Mode</source>
        <translation>Modo de A&amp;presentação</translation>
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
        <translation>Ecrã inteiro, a escala de interface da apresentação, a vista em grande (F6: os painéis)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the Panels in Presentation &amp;Mode</source>
        <translation>Mostrar os Painéis no &amp;Modo de Apresentação</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>F6</source>
        <translation>F6</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Blank the Screen (Presentation Mode)</source>
        <translation>&amp;Escurecer o Ecrã (Modo de Apresentação)</translation>
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
        <translation>Setas da Sonda Esba&amp;tidas</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The probe&apos;s arrows thin and see-through, so the highlight under them stays visible</source>
        <translation>As setas da sonda finas e translúcidas, para que o reflexo especular por baixo delas continue visível</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>B or . blanks the screen in presentation mode (F5 or F11); Phong / Blinn-Phong is Ctrl+B</source>
        <translation>B ou . escurece o ecrã no modo de apresentação (F5 ou F11); Phong / Blinn-Phong é Ctrl+B</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Presentation mode (F5) will show the panels (F6 hides them)</source>
        <translation>O modo de apresentação (F5) vai mostrar os painéis (F6 esconde-os)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Presentation mode (F5) will hide the panels (F6 shows them)</source>
        <translation>O modo de apresentação (F5) vai esconder os painéis (F6 mostra-os)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The editor needs %1 px at this scale: View &gt; Shader editor shows it</source>
        <extracomment>View &gt; Shader editor: the menu&apos;s and the dock&apos;s names as translated there</extracomment>
        <translation>O editor precisa de %1 px nesta escala: Ver &gt; Editor de shaders mostra-o</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window_unsaved.cpp" line="-1"/>
        <source>Save the shader pair as NAME.vert and NAME.frag</source>
        <translation>Guardar o par de shaders como NAME.vert e NAME.frag</translation>
    </message>
</context>
<context>
    <name>lb::MaterialPanel</name>
    <message>
        <location filename="../../widgets/material_panel.cpp" line="+68"/>
        <source>Shininess</source>
        <translation>Brilho</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset material</source>
        <translation>Repor material</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The selected object&apos;s material back to the slides&apos; red plastic: Ka = Kd = (1, 0, 0), Ks = (1, 1, 1), n = 6</source>
        <translation>O material do objeto selecionado de volta ao plástico vermelho dos diapositivos: Ka = Kd = (1, 0, 0), Ks = (1, 1, 1), n = 6</translation>
    </message>
</context>
<context>
    <name>lb::MeshActions</name>
    <message>
        <location filename="../../app/window/mesh_actions.cpp" line="+68"/>
        <source>Open &amp;Recent Mesh</source>
        <translation>Abrir Malha Rece&amp;nte</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Texture not used</source>
        <translation>Textura não usada</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>An image could not be used as a texture.</source>
        <translation>Não foi possível usar uma imagem como textura.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Mesh not built</source>
        <translation>Malha não construída</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An object&apos;s mesh could not be built; it keeps what it drew before.</source>
        <translation>Não foi possível construir a malha de um objeto; ele mantém o que desenhava antes.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Open &amp;Mesh...</source>
        <translation>Abrir &amp;Malha...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+M</source>
        <translation>Ctrl+M</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open &amp;Texture Image...</source>
        <translation>Abrir Imagem de Textu&amp;ra...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+T</source>
        <translation>Ctrl+T</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Preferences...</source>
        <translation>Pre&amp;ferências...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ctrl+,</source>
        <translation>Ctrl+,</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;Normals</source>
        <translation>Mostrar as &amp;Normais</translation>
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
        <translation>%1 não carregado (desenha-se %2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 triangles, %3 s</source>
        <translation>%1: %2 triângulos, %3 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 triangles</source>
        <translation>%1: %2 triângulos</translation>
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
        <translation>Malhas que o Assimp lê (%1);;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation>Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open a mesh</source>
        <translation>Abrir uma malha</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Open an image as the selected object&apos;s texture</source>
        <translation>Abrir uma imagem como textura do objeto selecionado</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Images (%1);;All files (*)</source>
        <translation>Imagens (%1);;Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Mesh not loaded</source>
        <translation>Malha não carregada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A mesh file the scene names could not be loaded. Its objects draw their shapes and keep its name, so saving keeps it; it is read again after the file changes (at your next change to the scene) or when you open it.</source>
        <translation>Não foi possível carregar um ficheiro de malha referido pela cena. Os seus objetos desenham as suas formas e mantêm o nome dele, pelo que guardar o mantém; é lido de novo depois de o ficheiro mudar (na sua próxima alteração à cena) ou quando o abrir.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The mesh could not be loaded; the previous one stays.</source>
        <translation>Não foi possível carregar a malha; a anterior mantém-se.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Files not used</source>
        <translation>Ficheiros não usados</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Some files could not be used.</source>
        <translation>Não foi possível usar alguns ficheiros.</translation>
    </message>
</context>
<context>
    <name>lb::MeshFile</name>
    <message>
        <location filename="../../render/model/mesh/mesh_file.cpp" line="+41"/>
        <source>%1 points, lines or broken faces skipped</source>
        <translation>%1 pontos, linhas ou faces defeituosas ignorados</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 vertices with non-finite coordinates dropped, with the %2 triangles using them</source>
        <translation>%1 vértices com coordenadas não finitas descartados, com os %2 triângulos que os usam</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 normals with non-finite coordinates: the file&apos;s normals not used</source>
        <translation>%1 normais com coordenadas não finitas: as normais do ficheiro não foram usadas</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: %2 vertices, %3 triangles</source>
        <translation>%1: %2 vértices, %3 triângulos</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s</source>
        <translation>%1: %2 vértices, %3 triângulos, carregado em %4 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s, normals generated</source>
        <translation>%1: %2 vértices, %3 triângulos, carregado em %4 s, normais geradas</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 vertices, %3 triangles, loaded in %4 s, normals generated (the file has none)</source>
        <translation>%1: %2 vértices, %3 triângulos, carregado em %4 s, normais geradas (o ficheiro não tem nenhuma)</translation>
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
        <translation>faces viradas: o ficheiro ordena-as no sentido dos ponteiros do relógio</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>faces of %1 of %2 closed parts turned: the file winds them clockwise</source>
        <translation>faces de %1 de %2 partes fechadas viradas: o ficheiro ordena-as no sentido dos ponteiros do relógio</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>normals turned: the file&apos;s point inwards</source>
        <translation>normais viradas: as do ficheiro apontam para dentro</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>normals of %1 of %2 closed parts turned: the file&apos;s point inwards</source>
        <translation>normais de %1 de %2 partes fechadas viradas: as do ficheiro apontam para dentro</translation>
    </message>
</context>
<context>
    <name>lb::MessageText</name>
    <message>
        <location filename="../../render/model/io/message_text.cpp" line="+85"/>
        <source>... and %1 more</source>
        <translation>... e mais %1</translation>
    </message>
</context>
<context>
    <name>lb::NumberBox</name>
    <message>
        <location filename="../../widgets/number_box.cpp" line="+68"/>
        <source>Not a number: digits, a sign in front and one decimal separator.</source>
        <translation>Não é um número: algarismos, um sinal à frente e um só separador decimal.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A whole number, typed without separators.</source>
        <translation>Um número inteiro, escrito sem separadores.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One decimal separator, a point or a comma (2.5 or 2,5), and no thousands separators.</source>
        <translation>Um só separador decimal, um ponto ou uma vírgula (2.5 ou 2,5), e sem separadores de milhares.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This box takes whole numbers.</source>
        <translation>Esta caixa aceita números inteiros.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>This box takes %n decimal(s).</source>
        <translation>
            <numerusform>Esta caixa aceita %n casa decimal.</numerusform>
            <numerusform>Esta caixa aceita %n casas decimais.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This box takes %1 to %2.</source>
        <extracomment>%1 the lowest number the box takes, %2 the highest (with their units)</extracomment>
        <translation>Esta caixa aceita de %1 a %2.</translation>
    </message>
</context>
<context>
    <name>lb::ObjectLoader</name>
    <message>
        <location filename="../../render/import/object_loader_textures.cpp" line="+67"/>
        <source>%1 (the objects naming it show the mesh file&apos;s texture or the checker, and keep its name for when the file is back)</source>
        <translation>%1 (os objetos que o referem mostram a textura do ficheiro da malha ou o xadrez, e guardam o seu nome para quando o ficheiro voltar)</translation>
    </message>
    <message>
        <location filename="../../render/import/object_loader.cpp" line="+173"/>
        <source>%1: not used: its object was removed</source>
        <translation>%1: não usado: o seu objeto foi removido</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>%1: not loaded: cancelled</source>
        <translation>%1: não carregado: cancelado</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: not loaded: its object was removed</source>
        <translation>%1: não carregado: o seu objeto foi removido</translation>
    </message>
    <message>
        <location filename="../../app/window/mesh_actions.cpp" line="-25"/>
        <location filename="../../render/import/object_loader.cpp" line="+2"/>
        <location line="+186"/>
        <source>Loading cancelled</source>
        <translation>Carregamento cancelado</translation>
    </message>
    <message>
        <location filename="../../render/import/object_loader.cpp" line="-62"/>
        <source>building</source>
        <translation>a construir</translation>
    </message>
</context>
<context>
    <name>lb::ObjectMesh</name>
    <message>
        <location filename="../../render/model/mesh/object_mesh.cpp" line="+34"/>
        <source>out of memory building %1&apos;s normals (%2 triangles)</source>
        <translation>sem memória para construir as normais de %1 (%2 triângulos)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>out of memory building the cube</source>
        <translation>sem memória para construir o cubo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>out of memory building the sphere at tessellation %1</source>
        <translation>sem memória para construir a esfera com tesselação %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>out of memory building the torus at tessellation %1</source>
        <translation>sem memória para construir o toro com tesselação %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>out of memory building the plane at tessellation %1</source>
        <translation>sem memória para construir o plano com tesselação %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+103"/>
        <source>out of memory building a mesh</source>
        <translation>sem memória para construir uma malha</translation>
    </message>
</context>
<context>
    <name>lb::ObjectPanel</name>
    <message>
        <location filename="../../widgets/object_panel.cpp" line="+31"/>
        <source>The scene&apos;s objects, each with its own mesh, transform and material: select one to edit it here and in the Material panel (or click it in the view). Untick to hide; double-click to rename</source>
        <translation>Os objetos da cena, cada um com a sua malha, transformação e material: selecione um para o editar aqui e no painel Material (ou clique nele na vista). Desmarque para esconder; duplo clique para mudar o nome</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Add</source>
        <translation>Adicionar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new sphere in the first free place near the centre (at most %1 objects; R frames them all)</source>
        <translation>Uma nova esfera no primeiro lugar livre perto do centro (no máximo %1 objetos; R enquadra-os todos)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Duplicate</source>
        <translation>Duplicar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A copy of the selected object, material and all, in the first free place near the centre</source>
        <translation>Uma cópia do objeto selecionado, com material e tudo, no primeiro lugar livre perto do centro</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 copy</source>
        <translation>%1 - cópia</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remove</source>
        <translation>Remover</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Removes the selected object (the last one stays); lights in its frame go to the object before it</source>
        <translation>Remove o objeto selecionado (o último fica); as luzes no seu referencial passam para o objeto anterior</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cube (flat faces)</source>
        <translation>Cubo (faces planas)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Sphere (smooth)</source>
        <translation>Esfera (suave)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Torus</source>
        <translation>Toro</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Plane</source>
        <translation>Plano</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The object: vPosition and vNormal come from this mesh. A built-in shape replaces a mesh file</source>
        <translation>O objeto: vPosition e vNormal vêm desta malha. Uma forma integrada substitui um ficheiro de malha</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Open...</source>
        <translation>Abrir...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a mesh file: any format Assimp reads (Ctrl+M; or drop a file on the window)</source>
        <translation>Abrir um ficheiro de malha: qualquer formato que o Assimp leia (Ctrl+M; ou largue um ficheiro na janela)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Subdivisions of the sphere, torus and plane. Few vertices show Gouraud&apos;s weakness: its highlight follows the vertices</source>
        <translation>Subdivisões da esfera, do toro e do plano. Poucos vértices mostram a fraqueza de Gouraud: o seu reflexo especular segue os vértices</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Tessellation</source>
        <translation>Tesselação</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From the mesh</source>
        <translation>Da malha</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Smooth (crease angle)</source>
        <translation>Suaves (ângulo de vinco)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flat</source>
        <translation>Planas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vNormal: the mesh&apos;s own normals (generated smooth when a file has none), or generated: smooth, averaged over the triangles around a vertex within the crease angle, or flat, one per triangle</source>
        <translation>vNormal: as normais da própria malha (geradas suaves quando um ficheiro não as tem), ou geradas: suaves, a média dos triângulos em torno de um vértice dentro do ângulo de vinco, ou planas, uma por triângulo</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Normals</source>
        <translation>Normais</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outward</source>
        <translation>Para fora</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>As in the file</source>
        <translation>Como no ficheiro</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flipped</source>
        <translation>Invertidas</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Both sides lit</source>
        <translation>Ambos os lados iluminados</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which way a mesh file&apos;s faces look. Outward: a closed part wound inwards (lit from inside) is turned, with its normals, and the status line says so; as in the file; every face flipped; or both sides lit, each with the normal facing the camera (for open meshes: a sheet, a scan with holes)</source>
        <translation>Para onde olham as faces de um ficheiro de malha. Para fora: uma parte fechada orientada para dentro (iluminada por dentro) é virada, com as suas normais, e a linha de estado di-lo; como no ficheiro; todas as faces invertidas; ou ambos os lados iluminados, cada um com a normal virada para a câmara (para malhas abertas: uma folha, um scan com buracos)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Faces</source>
        <translation>Faces</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Generated smooth normals average only triangles that meet at less than this angle: 0 is flat, 180 smooths every edge</source>
        <translation>As normais suaves geradas só fazem a média de triângulos que se encontram a menos deste ângulo: 0 é plano, 180 suaviza todas as arestas</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Crease angle</source>
        <translation>Ângulo de vinco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show normals as lines</source>
        <translation>Mostrar as normais como linhas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A short line along each vertex normal, transformed by mNormals as the shaders do (key N)</source>
        <translation>Uma linha curta ao longo de cada normal de vértice, transformada por mNormals como os shaders fazem (tecla N)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cull back faces (closed meshes)</source>
        <translation>Descartar as faces traseiras (malhas fechadas)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Triangles facing away from the camera are not drawn: the same picture for a closed mesh, about twice as fast; an open mesh shows holes where its inside was</source>
        <translation>Os triângulos virados para o lado oposto à câmara não são desenhados: a mesma imagem para uma malha fechada, cerca de duas vezes mais rápido; uma malha aberta mostra buracos onde estava o seu interior</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Use the mesh file&apos;s material</source>
        <translation>Usar o material do ficheiro da malha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The mesh file&apos;s ambient, diffuse and specular colours and shininess replace Ka, Kd, Ks and shininess: now, and whenever a file is loaded</source>
        <translation>As cores ambiente, difusa e especular e o brilho do ficheiro da malha substituem Ka, Kd, Ks e o brilho: agora, e sempre que um ficheiro for carregado</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Rotation about %1 in degrees (model matrix; applied X, then Y, then Z)</source>
        <translation>Rotação em torno de %1 em graus (matriz de modelo; aplicada em X, depois Y, depois Z)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Scale along %1. A non-uniform scale is why normals need mNormals, the inverse transpose of mModelView</source>
        <translation>Escala segundo %1. Uma escala não uniforme é a razão pela qual as normais precisam de mNormals, a transposta da inversa de mModelView</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Translation along world %1: where the object&apos;s centre lies (model matrix, applied last)</source>
        <translation>Translação segundo %1 do mundo: onde fica o centro do objeto (matriz de modelo, aplicada por último)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Rotate</source>
        <extracomment>the row of the object&apos;s rotation about X, Y and Z</extracomment>
        <translation>Rodar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scale</source>
        <extracomment>the row of the object&apos;s scale along X, Y and Z</extracomment>
        <translation>Escala</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move</source>
        <extracomment>the row of the object&apos;s translation along X, Y and Z</extracomment>
        <translation>Mover</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Auto-rotate about Y</source>
        <translation>Rodar automaticamente em torno de Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turns the model: a light in the object frame turns with it (key Space)</source>
        <translation>Roda o modelo: uma luz no referencial do objeto roda com ele (tecla Espaço)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reset object</source>
        <translation>Repor objeto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The selected object back to the coarse unit sphere, unrotated, unscaled and not turning; its name, place and material stay</source>
        <translation>O objeto selecionado de volta à esfera unitária grosseira, sem rotação, sem escala e parado; o seu nome, lugar e material mantêm-se</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>File: %1</source>
        <extracomment>the shape combo&apos;s entry for a mesh file; %1 the file&apos;s name</extracomment>
        <translation>Ficheiro: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File: %1 (not loaded)</source>
        <translation>Ficheiro: %1 (não carregado)</translation>
    </message>
</context>
<context>
    <name>lb::Offscreen</name>
    <message>
        <location filename="../../render/gl/offscreen.cpp" line="+49"/>
        <source>cannot create an OpenGL context (is there an X server with OpenGL?)</source>
        <translation>não é possível criar um contexto OpenGL (existe um servidor X com OpenGL?)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cannot make the OpenGL context current</source>
        <translation>não é possível tornar atual o contexto OpenGL</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>OpenGL 3.3 is needed, the driver gives %1.%2</source>
        <translation>é necessário OpenGL 3.3, o controlador oferece %1.%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>cannot create a %1x%2 framebuffer</source>
        <translation>não é possível criar um framebuffer de %1x%2</translation>
    </message>
</context>
<context>
    <name>lb::PlotChart</name>
    <message>
        <location filename="../../widgets/plot_chart.cpp" line="+175"/>
        <source>Angle between R and V (°)</source>
        <translation>Ângulo entre R e V (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle between N and L (°)</source>
        <translation>Ângulo entre N e L (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance d from the light</source>
        <translation>Distância d à luz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle from the spot&apos;s axis (°)</source>
        <translation>Ângulo ao eixo do foco (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specular factor</source>
        <translation>Fator especular</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spot factor</source>
        <translation>Fator do foco</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Surface</source>
        <translation>Superfície</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Specular factor&lt;br&gt;&lt;small&gt;Phong (R·V)^n, Blinn-Phong (N·H)^n; dashed: Blinn-Phong at 4n&lt;/small&gt;</source>
        <translation>Fator especular&lt;br&gt;&lt;small&gt;Phong (R·V)^n, Blinn-Phong (N·H)^n; tracejado: Blinn-Phong com 4n&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Diffuse factor&lt;br&gt;&lt;small&gt;against the angle of incidence&lt;/small&gt;</source>
        <translation>Fator difuso&lt;br&gt;&lt;small&gt;em função do ângulo de incidência&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Attenuation&lt;br&gt;&lt;small&gt;against the distance from the light&lt;/small&gt;</source>
        <translation>Atenuação&lt;br&gt;&lt;small&gt;em função da distância à luz&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Spotlight factor&lt;br&gt;&lt;small&gt;against the angle from its axis&lt;/small&gt;</source>
        <translation>Fator do foco&lt;br&gt;&lt;small&gt;em função do ângulo ao eixo&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The three terms as V sweeps&lt;br&gt;&lt;small&gt;the plane of incidence, N up; radius: the mean of red, green and blue&lt;/small&gt;</source>
        <translation>Os três termos enquanto V percorre&lt;br&gt;&lt;small&gt;o plano de incidência, N para cima; raio: média do vermelho, verde e azul&lt;/small&gt;</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>No point light is on: a directional light (w = 0) is not attenuated.</source>
        <translation>Nenhuma luz pontual está ligada: uma luz direcional (w = 0) não é atenuada.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No spotlight: every light that is on has a cutoff of 180°. Set a cutoff in the Light panel.</source>
        <translation>Nenhum foco: todas as luzes ligadas têm um ângulo de corte de 180°. Defina um ângulo de corte no painel Luz.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No light is on.</source>
        <translation>Nenhuma luz está ligada.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No lobe: the light is at the surface&apos;s point, where L has no direction. Move the light off the surface.</source>
        <translation>Sem lóbulo: a luz está no ponto da superfície, onde L não tem direção. Afaste a luz da superfície.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Ambient</source>
        <translation>Ambiente</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse</source>
        <translation>Difusa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Specular</source>
        <translation>Especular</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light %1</source>
        <translation>Luz %1</translation>
    </message>
</context>
<context>
    <name>lb::PlotsPanel</name>
    <message>
        <location filename="../../widgets/plots_panel.cpp" line="+42"/>
        <source>Specular: Phong and Blinn-Phong</source>
        <translation>Especular: Phong e Blinn-Phong</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diffuse: max(N·L, 0)</source>
        <translation>Difusa: max(N·L, 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attenuation with distance</source>
        <translation>Atenuação com a distância</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spotlight falloff</source>
        <translation>Decaimento do foco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lobe at the probed point</source>
        <translation>Lóbulo no ponto sondado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which of the model&apos;s curves to draw</source>
        <translation>Que curva do modelo desenhar</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export…</source>
        <translation>Exportar…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write this plot as a PNG or SVG picture, or its samples as CSV</source>
        <translation>Gravar este gráfico como imagem PNG ou SVG, ou as suas amostras como CSV</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>No point probed: light %1&apos;s lobe where N faces the camera at the selected object&apos;s centre. Ctrl+click the surface to plot it at a point.</source>
        <translation>Nenhum ponto sondado: o lóbulo da luz %1 onde N aponta para a câmara no centro do objeto selecionado. Ctrl+clique na superfície para o desenhar num ponto.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Ctrl+click the surface: the probed point&apos;s own values appear as dots.</source>
        <translation>Ctrl+clique na superfície: os valores do ponto sondado aparecem como pontos.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light %1&apos;s terms at the probed point. The dots are where V&apos;s part in the plane of incidence points; the Probe tab has the values at V itself.</source>
        <translation>Os termos da luz %1 no ponto sondado. Os pontos estão onde aponta a parte de V no plano de incidência; o painel Sonda tem os valores no próprio V.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No dot: at the probed point every light is behind the surface (N·L &lt; 0) or outside the plot.</source>
        <translation>Sem ponto: no ponto sondado todas as luzes estão atrás da superfície (N·L &lt; 0) ou fora do gráfico.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Dots: each light&apos;s angle at the probed point (for Blinn-Phong, 2·acos(N·H)).</source>
        <translation>Pontos: o ângulo de cada luz no ponto sondado (em Blinn-Phong, 2·acos(N·H)).</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>PNG images (*.png)</source>
        <translation>Imagens PNG (*.png)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SVG pictures (*.svg)</source>
        <translation>Imagens SVG (*.svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV samples (*.csv)</source>
        <translation>Amostras CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+15"/>
        <source>Export the plot</source>
        <translation>Exportar o gráfico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The plot could not be written; nothing was changed.
%1</source>
        <translation>Não foi possível gravar o gráfico; nada foi alterado.
%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported the plot to %1</source>
        <translation>Gráfico exportado para %1</translation>
    </message>
</context>
<context>
    <name>lb::PreferencesDialog</name>
    <message>
        <location filename="../../widgets/preferences_dialog.cpp" line="+15"/>
        <source>Preferences</source>
        <translation>Preferências</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mesh files are read by a helper process (lightbench-import). When it needs more memory or time than this, it is stopped and the file gets a message; the workbench carries on.</source>
        <translation>Os ficheiros de malha são lidos por um processo auxiliar (lightbench-import). Quando precisa de mais memória ou tempo do que isto, é parado e o ficheiro recebe uma mensagem; a bancada de trabalho continua.</translation>
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
        <translation>O limite do espaço de endereçamento do processo auxiliar. Predefinição: metade da memória desta máquina (%1 MB). Também --import-memory-limit MB</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Import memory limit</source>
        <translation>Limite de memória da importação</translation>
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
        <translation>Um carregamento que demore mais é parado. Predefinição: %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import time limit</source>
        <translation>Limite de tempo da importação</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Your shader program is tried on tiny frames before it draws; when one frame at the view&apos;s size would take longer than this, it is refused and the last good program keeps drawing. Default: %1 s. Also --frame-budget SECONDS</source>
        <translation>O seu programa de shaders é testado em fotogramas minúsculos antes de desenhar; quando um fotograma no tamanho da vista demoraria mais do que isto, é recusado e o último programa válido continua a desenhar. Predefinição: %1 s. Também --frame-budget SECONDS</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Frame budget</source>
        <translation>Orçamento de tempo por fotograma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move the camera and the lights smoothly between a lesson&apos;s steps</source>
        <translation>Mover a câmara e as luzes suavemente entre os passos de uma lição</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>So the class sees where they go; off: each step jumps</source>
        <translation>Para que a turma veja para onde vão; desligado: cada passo salta</translation>
    </message>
</context>
<context>
    <name>lb::Presets</name>
    <message>
        <location filename="../../render/glsl/presets.cpp" line="+37"/>
        <source>Built-in: Phong shading (per fragment)</source>
        <translation>Integrado: sombreamento de Phong (por fragmento)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Built-in: Gouraud shading (per vertex)</source>
        <translation>Integrado: sombreamento de Gouraud (por vértice)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Slides: Gouraud, WebGL 1 as printed</source>
        <translation>Diapositivos: Gouraud, WebGL 1 tal como impresso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Slides: Phong shading, WebGL 1 as printed</source>
        <translation>Diapositivos: sombreamento de Phong, WebGL 1 tal como impresso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Toon (the exercise&apos;s &quot;like Zelda&quot;), GLSL 3.30</source>
        <translation>Toon (o &quot;como o Zelda&quot; do exercício), GLSL 3.30</translation>
    </message>
</context>
<context>
    <name>lb::ProbeEquation</name>
    <message>
        <location filename="../../render/model/measure/probe_equation.cpp" line="+150"/>
        <source>Lighting is off: the surface shows Kd times the base colour instead.</source>
        <translation>A iluminação está desligada: em vez disto, a superfície mostra Kd vezes a cor de base.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Flat shading draws the model at the triangle&apos;s last (provoking) vertex, one colour for the triangle; these numbers are the model at this point.</source>
        <translation>O sombreamento plano desenha o modelo calculado no último vértice do triângulo (o provoking vertex), uma só cor para todo o triângulo; estes números são os do modelo neste ponto.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Gouraud shading draws the model at the triangle&apos;s vertices, interpolated; these numbers are the model at this point.</source>
        <translation>O sombreamento de Gouraud desenha o modelo calculado nos vértices do triângulo e interpolado; estes números são os do modelo neste ponto.</translation>
    </message>
    <message>
        <location line="-72"/>
        <source>(base multiplies ambient and diffuse only)</source>
        <extracomment>after the equation in symbols, where a texture&apos;s base colour multiplies it</extracomment>
        <translation>(base multiplica só os termos ambiente e difuso)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>(0: the light is behind the surface)</source>
        <extracomment>after the specular term&apos;s numbers, where N·L &lt; 0</extracomment>
        <translation>(0: a luz está atrás da superfície)</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>[off]</source>
        <extracomment>before a term the Shading panel switched off</extracomment>
        <translation>[desligado]</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>light %1: %2</source>
        <extracomment>a light&apos;s line of the equation: %1 its number, %2 its factors (att·spot = ...)</extracomment>
        <translation>luz %1: %2</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>pixel = %1 of 255 (clamped to 0..1)</source>
        <extracomment>%1 the pixel&apos;s red, green and blue, as (r, g, b)</extracomment>
        <translation>píxel = %1 de 255 (limitado a 0..1)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The surface shows %1, not this colour.</source>
        <extracomment>%1 what the Shading panel&apos;s Show choice draws instead (normal, ndotl, ...)</extracomment>
        <translation>A superfície mostra %1, não esta cor.</translation>
    </message>
</context>
<context>
    <name>lb::ProbePanel</name>
    <message>
        <location filename="../../widgets/probe_panel.cpp" line="+68"/>
        <source>Copy the Equation</source>
        <translation>Copiar a Equação</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The lighting equation with this point&apos;s numbers, as text</source>
        <translation>A equação de iluminação com os números deste ponto, como texto</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Ctrl+click (or Shift+click) the surface to probe a point: the vectors, N·L, the specular angle and the three terms, beside the pixel the GPU drew. Esc clears it.</source>
        <translation>Ctrl+clique (ou Shift+clique) na superfície para sondar um ponto: os vetores, N·L, o ângulo especular e os três termos, ao lado do píxel que a GPU desenhou. Esc limpa-o.</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>No surface at (%1, %2).</source>
        <translation>Nenhuma superfície em (%1, %2).</translation>
    </message>
    <message>
        <location line="+107"/>
        <source>pixel (%1, %2), %3, triangle %4</source>
        <extracomment>%1, %2 the pixel; %3 the object&apos;s name; %4 the triangle&apos;s number</extracomment>
        <translation>píxel (%1, %2), %3, triângulo %4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pixel (%1, %2), %3, triangle %4, side B</source>
        <translation>píxel (%1, %2), %3, triângulo %4, lado B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pixel (%1, %2), %3, triangle %4, side A</source>
        <translation>píxel (%1, %2), %3, triângulo %4, lado A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Point</source>
        <translation>Ponto</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>P (eye)</source>
        <extracomment>P, the probed point, in eye coordinates</extracomment>
        <translation>P (olho)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>levels %1 and %2 (%3% of %2)</source>
        <translation>níveis %1 e %2 (%3% do %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>level %1</source>
        <translation>nível %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>uv (%1, %2), level of detail %3: %4, mipmaps</source>
        <extracomment>%1, %2 the texture coordinates; %3 the level of detail; %4 the mipmap levels read</extracomment>
        <translation>uv (%1, %2), nível de detalhe %3: %4, mipmaps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uv (%1, %2), level of detail %3: %4, no mipmaps</source>
        <translation>uv (%1, %2), nível de detalhe %3: %4, sem mipmaps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>texture</source>
        <translation>textura</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>base colour</source>
        <translation>cor de base</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (%2 frame)</source>
        <extracomment>%1 the light&apos;s name in bold (Light 2); %2 its frame (camera, world, object)</extracomment>
        <translation>%1 (referencial: %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Light %1</source>
        <translation>Luz %1</translation>
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
        <translation>distância, atenuação</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>spot</source>
        <translation>foco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 (outside the cone)</source>
        <translation>0 (fora do cone)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (off)</source>
        <translation>%1 (desligado)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+5"/>
        <source>ambient</source>
        <translation>ambiente</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+5"/>
        <source>diffuse</source>
        <translation>difuso</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+5"/>
        <source>specular</source>
        <translation>especular</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Sum</source>
        <translation>Soma</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the model (%1 shading)</source>
        <translation>o modelo (sombreamento %1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 of 255 (the built-in model, %2 shading)</source>
        <extracomment>%1 the colour (r, g, b) of 255; %2 the shading (gouraud, phong, flat)</extracomment>
        <translation>%1 de 255 (o modelo integrado, sombreamento %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of 255 (%2 shading)</source>
        <translation>%1 de 255 (sombreamento %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>model</source>
        <translation>modelo</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+3"/>
        <source>reference</source>
        <translation>referência</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 draws nothing here</source>
        <translation>%1 não desenha nada aqui</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>%1 draws %2</source>
        <extracomment>%1 the reference&apos;s name; %2 its colour (r, g, b) at the point</extracomment>
        <translation>%1 desenha %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>GPU drew</source>
        <translation>a GPU desenhou</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>difference</source>
        <translation>diferença</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of 255 from %2</source>
        <translation>%1 de 255 face a %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 of 255</source>
        <translation>%1 de 255</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The equation at this point</source>
        <translation>A equação neste ponto</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>This point is drawn by %1 (side B), which is itself the reference: it is compared with nothing. The numbers above are the built-in model&apos;s, which that program need not follow.</source>
        <translation>Este ponto é desenhado por %1 (lado B), que é ele próprio a referência: não é comparado com nada. Os números acima são os do modelo integrado, que esse programa não tem de seguir.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The pixel is compared with what %1 draws at this point; the numbers above are the built-in model&apos;s.</source>
        <translation>O píxel é comparado com o que %1 desenha neste ponto; os números acima são os do modelo integrado.</translation>
    </message>
</context>
<context>
    <name>lb::Program</name>
    <message>
        <location filename="../../render/gl/program.cpp" line="+75"/>
        <source>the vertex shader is empty</source>
        <translation>o vertex shader está vazio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fragment shader is empty</source>
        <translation>o fragment shader está vazio</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the vertex shader is %1 KiB; lightbench compiles sources up to %2 KiB</source>
        <translation>o vertex shader tem %1 KiB; o lightbench compila código-fonte até %2 KiB</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the fragment shader is %1 KiB; lightbench compiles sources up to %2 KiB</source>
        <translation>o fragment shader tem %1 KiB; o lightbench compila código-fonte até %2 KiB</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>the vertex shader does not compile (the driver gave no reason)</source>
        <translation>o vertex shader não compila (o controlador não indicou o motivo)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the fragment shader does not compile (the driver gave no reason)</source>
        <translation>o fragment shader não compila (o controlador não indicou o motivo)</translation>
    </message>
    <message>
        <location line="+285"/>
        <source>the program does not link (no reason given)</source>
        <translation>a ligação (link) do programa falhou (sem motivo indicado)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no position input: the mesh reaches the shader through the attribute at layout(location = 0), or one named aPos, a_position, vPosition, aVertexPosition or position, or with pos or vert in its name</source>
        <translation>sem entrada de posição: a malha chega ao shader através do atributo em layout(location = 0), ou de um chamado aPos, a_position, vPosition, aVertexPosition ou position, ou com pos ou vert no nome</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the fragment shader writes no colour: assign gl_FragColor (no #version, #version 100) or declare an out vec4 (#version 300 es, 330 and later)</source>
        <translation>o fragment shader não escreve nenhuma cor: atribua gl_FragColor (sem #version, #version 100) ou declare um out vec4 (#version 300 es, 330 e posteriores)</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>a global variable initialised from a uniform or another variable: GLSL ES 1.00 asks for a constant, browsers run it (WebGL warns); lightbench runs this program translated to GLSL 3.30 (the driver said: %1)</source>
        <translation>uma variável global inicializada a partir de um uniform ou de outra variável: o GLSL ES 1.00 exige uma constante, os browsers executam-na (o WebGL avisa); o lightbench executa este programa traduzido para GLSL 3.30 (o driver disse: %1)</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+88"/>
        <source>built-in shader &apos;%1&apos; failed:
%2</source>
        <extracomment>%1 a built-in program&apos;s name, %2 its build log</extracomment>
        <translation>o shader integrado &apos;%1&apos; falhou:
%2</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>built-in shader &apos;%1&apos; lacks a &apos;#define MAX_LIGHTS&apos;, &apos;LIGHT_FACTORS&apos; or &apos;SHOW_CHOICES&apos; line
</source>
        <translation>falta ao shader integrado &apos;%1&apos; uma linha &apos;#define MAX_LIGHTS&apos;, &apos;LIGHT_FACTORS&apos; ou &apos;SHOW_CHOICES&apos;
</translation>
    </message>
</context>
<context>
    <name>lb::ProgramGuard</name>
    <message>
        <location filename="../../render/pipeline/program_guard.cpp" line="+16"/>
        <source>the driver ran out of memory compiling or drawing this program (limit %1): a macro that doubles itself, or a program too big for it?</source>
        <translation>o controlador ficou sem memória ao compilar ou desenhar este programa (limite %1): uma macro que se duplica a si própria, ou um programa grande demais para ele?</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>compiling this program and drawing it on small frames took more than %1: an endless or very long loop, or a program too big for the driver?</source>
        <translation>compilar este programa e desenhá-lo em fotogramas pequenos demorou mais de %1: um ciclo infinito ou muito longo, ou um programa grande demais para o controlador?</translation>
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
        <translation>desenhar um fotograma com este programa a %1x%2 demoraria mais do que o seu orçamento de %3: um ciclo infinito ou muito longo?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>drawing one frame with this program at %1x%2 would take more than its budget of %3: too much work for every pixel?</source>
        <translation>desenhar um fotograma com este programa a %1x%2 demoraria mais do que o seu orçamento de %3: demasiado trabalho por píxel?</translation>
    </message>
</context>
<context>
    <name>lb::RecentFiles</name>
    <message>
        <location filename="../../widgets/recent_files.cpp" line="+55"/>
        <source>(none yet)</source>
        <translation>(ainda nenhum)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Clear the list</source>
        <translation>Limpar a lista</translation>
    </message>
</context>
<context>
    <name>lb::SafeWrite</name>
    <message>
        <location filename="../../render/model/io/safe_write.cpp" line="+57"/>
        <location line="+14"/>
        <source>a loop of symbolic links</source>
        <translation>um ciclo de ligações simbólicas</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not a regular file (a device, a pipe or a folder); not replaced</source>
        <translation>não é um ficheiro regular (é um dispositivo, um pipe ou uma pasta); não foi substituído</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>read-only (mode %1); not replaced</source>
        <translation>só de leitura (modo %1); não foi substituído</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the folder %1 does not exist</source>
        <translation>a pasta %1 não existe</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is not a folder</source>
        <translation>%1 não é uma pasta</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot write in %1: %2</source>
        <translation>não é possível escrever em %1: %2</translation>
    </message>
    <message>
        <location line="+127"/>
        <source>no image to write</source>
        <translation>nenhuma imagem para escrever</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the PNG could not be encoded</source>
        <translation>não foi possível codificar o PNG</translation>
    </message>
</context>
<context>
    <name>lb::Scene</name>
    <message>
        <location filename="../../render/model/scene/scene.cpp" line="+391"/>
        <source>cube</source>
        <translation>cubo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sphere</source>
        <translation>esfera</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>torus</source>
        <translation>toro</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>plane</source>
        <translation>plano</translation>
    </message>
</context>
<context>
    <name>lb::SceneActions</name>
    <message>
        <location filename="../../app/window/scene_actions.cpp" line="+34"/>
        <source>Scenes (*.lbscene *.json);;All files (*)</source>
        <translation>Cenas (*.lbscene *.json);;Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Scenes (*.json)</source>
        <translation>Cenas (*.json)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lightbench scenes (*.lbscene)</source>
        <translation>Cenas do lightbench (*.lbscene)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Open Recent S&amp;cene</source>
        <translation>Abrir &amp;Cena Recente</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Gouraud vs Phong (the slides)</source>
        <translation>Gouraud vs Phong (os diapositivos)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phong vs Blinn-Phong specular</source>
        <translation>Especular Phong vs Blinn-Phong</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The three light frames</source>
        <translation>Os três referenciais da luz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The normal matrix</source>
        <translation>A matriz das normais</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toon shading</source>
        <translation>Sombreamento toon</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The terms one at a time (keys A, D, S)</source>
        <translation>Os termos um a um (teclas A, D, S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attenuation of a point light</source>
        <translation>Atenuação de uma luz pontual</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A spotlight</source>
        <translation>Um holofote</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The exercise: a textured cube and a sphere, light in camera coordinates</source>
        <translation>O exercício: um cubo com textura e uma esfera, luz em coordenadas da câmara</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A light in one object&apos;s frame (it turns with the torus)</source>
        <translation>Uma luz no referencial de um objeto (roda com o toro)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Texture filtering: nearest, linear and mipmaps</source>
        <translation>Filtragem de texturas: mais próximo, linear e mipmaps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exercise: per-fragment lighting (Check My Work, F9)</source>
        <translation>Exercício: iluminação por fragmento (Verificar o Meu Trabalho, F9)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Open Scene...</source>
        <translation>&amp;Abrir Cena...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>E&amp;xamples</source>
        <translation>E&amp;xemplos</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Save Scene</source>
        <translation>&amp;Guardar Cena</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save Scene &amp;As...</source>
        <translation>Guardar Cena C&amp;omo...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>E&amp;xport Image...</source>
        <translation>Ex&amp;portar Imagem...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cop&amp;y Image</source>
        <translation>Cop&amp;iar Imagem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The scene could not be opened; nothing changed.</source>
        <translation>Não foi possível abrir a cena; nada mudou.</translation>
    </message>
    <message numerus="yes">
        <location line="+41"/>
        <source>%n field(s) could not be used and kept their defaults:</source>
        <translation>
            <numerusform>%n campo não pôde ser usado e ficou com o valor predefinido:</numerusform>
            <numerusform>%n campos não puderam ser usados e ficaram com os valores predefinidos:</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This step opened with less tessellation than it asks for, to fit this machine&apos;s memory; the file is unchanged unless you save the scene.</source>
        <translation>Abriu-se este passo com menos tesselação do que pede, para caber na memória desta máquina; o ficheiro fica inalterado a menos que guarde a cena.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 opened with less tessellation than it asks for, to fit this machine&apos;s memory; the file is unchanged unless you save the scene.</source>
        <translation>Abriu-se %1 com menos tesselação do que pede, para caber na memória desta máquina; o ficheiro fica inalterado a menos que guarde a cena.</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>This step opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>Abriu-se este passo; %n campo não pôde ser usado e ficou com o valor predefinido.</numerusform>
            <numerusform>Abriu-se este passo; %n campos não puderam ser usados e ficaram com os valores predefinidos.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 opened; %n field(s) could not be used and kept their defaults.</source>
        <translation>
            <numerusform>Abriu-se %1; %n campo não pôde ser usado e ficou com o valor predefinido.</numerusform>
            <numerusform>Abriu-se %1; %n campos não puderam ser usados e ficaram com os valores predefinidos.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Opened the scene %1</source>
        <translation>Abriu-se a cena %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The scene was not saved.</source>
        <translation>A cena não foi guardada.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved the scene to %1</source>
        <translation>Cena guardada em %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: not drawn: %2</source>
        <translation>%1: não desenhado: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the view could not be drawn at %2 x %3</source>
        <translation>%1: não foi possível desenhar a vista a %2 x %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The image was not exported.</source>
        <translation>A imagem não foi exportada.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported %1</source>
        <translation>Imagem exportada para %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Copied the view (%1 x %2) to the clipboard</source>
        <translation>Vista (%1 x %2) copiada para a área de transferência</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Open a scene</source>
        <translation>Abrir uma cena</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Save the scene</source>
        <translation>Guardar a cena</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All files (*)</source>
        <translation>Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export the view</source>
        <translation>Exportar a vista</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PNG images (*.png);;All files (*)</source>
        <translation>Imagens PNG (*.png);;Todos os ficheiros (*)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Scene</source>
        <translation>Cena</translation>
    </message>
</context>
<context>
    <name>lb::SceneBudget</name>
    <message>
        <location filename="../../render/model/mesh/scene_budget.cpp" line="+60"/>
        <location line="+2"/>
        <source>%1 million</source>
        <translation>%1 milhões</translation>
    </message>
    <message numerus="yes">
        <location line="+15"/>
        <source>%n object(s) at tessellation %1 would make %2 triangles (~%3)</source>
        <extracomment>what a scene asks for; %n the objects in the scene</extracomment>
        <translation>
            <numerusform>%n objeto com tesselação %1 daria %2 triângulos (~%3)</numerusform>
            <numerusform>%n objetos com tesselação %1 dariam %2 triângulos (~%3)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n object(s) at tessellation up to %1 would make %2 triangles (~%3)</source>
        <translation>
            <numerusform>%n objeto com tesselação até %1 daria %2 triângulos (~%3)</numerusform>
            <numerusform>%n objetos com tesselação até %1 dariam %2 triângulos (~%3)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>tessellation lowered to %1 on %n object(s) (%2) to fit %3, the most a scene may take on this machine (%4 of memory): %5 triangles now</source>
        <extracomment>what was done about it; %n the objects lowered, %2 their names</extracomment>
        <translation>
            <numerusform>tesselação reduzida para %1 em %n objeto (%2) para caber em %3, o máximo que uma cena pode ocupar nesta máquina (%4 de memória): agora %5 triângulos</numerusform>
            <numerusform>tesselação reduzida para %1 em %n objetos (%2) para caber em %3, o máximo que uma cena pode ocupar nesta máquina (%4 de memória): agora %5 triângulos</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>tessellation lowered to %1 on %n object(s) (%2) and still over %3, the most a scene may take on this machine (%4 of memory): ~%5 (its mesh files count in full)</source>
        <translation>
            <numerusform>tesselação reduzida para %1 em %n objeto (%2) e ainda acima de %3, o máximo que uma cena pode ocupar nesta máquina (%4 de memória): ~%5 (os ficheiros de malha da cena contam por inteiro)</numerusform>
            <numerusform>tesselação reduzida para %1 em %n objetos (%2) e ainda acima de %3, o máximo que uma cena pode ocupar nesta máquina (%4 de memória): ~%5 (os ficheiros de malha da cena contam por inteiro)</numerusform>
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
        <translation>não é true nem false; lido como false</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>%1: not a scene file: %2 at byte %3</source>
        <extracomment>%1 a path, %2 Qt&apos;s JSON parser&apos;s reason</extracomment>
        <translation>%1: não é um ficheiro de cena: %2 no byte %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: not a scene file: the JSON is not an object</source>
        <translation>%1: não é um ficheiro de cena: o JSON não é um objeto</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: a lesson file, not a scene file (open it as a lesson)</source>
        <translation>%1: um ficheiro de lição, não um ficheiro de cena (abra-o como lição)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>expected &quot;%1&quot;</source>
        <translation>era esperado &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>missing or not a number; read as %1</source>
        <translation>em falta ou não é um número; lido como %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>newer than this lightbench&apos;s %1: what it does not know is left out</source>
        <translation>mais recente do que a versão %1 deste lightbench: o que este não conhece fica de fora</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>needs vertex and fragment sources as strings</source>
        <translation>precisa do código-fonte do vertex shader e do fragment shader como strings</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the vertex shader has %1 characters, more than a shader may have (%2)</source>
        <extracomment>%1 the shader&apos;s characters; %2 the most a shader may have</extracomment>
        <translation>o vertex shader tem %1 caracteres, mais do que um shader pode ter (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the fragment shader has %1 characters, more than a shader may have (%2)</source>
        <extracomment>%1 the shader&apos;s characters; %2 the most a shader may have</extracomment>
        <translation>o fragment shader tem %1 caracteres, mais do que um shader pode ter (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not an object</source>
        <translation>não é um objeto</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 (the section is kept as it is)</source>
        <extracomment>%1 why an exercise section cannot be graded against</extracomment>
        <translation>%1 (a secção é mantida tal como está)</translation>
    </message>
</context>
<context>
    <name>lb::SceneJson</name>
    <message>
        <location filename="../../render/model/scene/scene_json.cpp" line="+230"/>
        <source>not one of the values the scene feeds (%1)</source>
        <translation>não é nenhum dos valores que a cena alimenta (%1)</translation>
    </message>
    <message>
        <location line="+76"/>
        <location line="+33"/>
        <source>not an array</source>
        <translation>não é um array</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>at most 4 lights</source>
        <translation>no máximo 4 luzes</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../../render/model/scene/scene_json_reader.cpp" line="+24"/>
        <source>not an object</source>
        <translation>não é um objeto</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>empty: one object drawn instead</source>
        <translation>vazio: é desenhado um objeto em vez disso</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>at most 32 objects; the rest left out</source>
        <translation>no máximo 32 objetos; os restantes ficam de fora</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not an object; a sphere in its place</source>
        <translation>não é um objeto; uma esfera no seu lugar</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>no such object; the first one</source>
        <translation>objeto inexistente; é usado o primeiro</translation>
    </message>
    <message>
        <location line="-159"/>
        <location line="+187"/>
        <source>too many: %1 more than the %2 kept</source>
        <translation>demasiados: %1 além dos %2 mantidos</translation>
    </message>
    <message>
        <location line="-180"/>
        <location line="+187"/>
        <source>not a uniform&apos;s name</source>
        <translation>não é o nome de um uniform</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>not 1 to 4 numbers</source>
        <translation>não são 1 a 4 números</translation>
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
        <translation>campo desconhecido</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+49"/>
        <source>not a number</source>
        <translation>não é um número</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not an array of numbers</source>
        <translation>não é um array de números</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+9"/>
        <source>out of range, clamped</source>
        <translation>fora do intervalo, ajustado ao limite</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not true or false</source>
        <translation>não é true nem false</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not a string</source>
        <translation>não é uma string</translation>
    </message>
    <message>
        <location filename="../../render/model/scene/scene_json_reader.h" line="+0"/>
        <source>not a whole number</source>
        <translation>não é um número inteiro</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>unknown value</source>
        <translation>valor desconhecido</translation>
    </message>
</context>
<context>
    <name>lb::ScenePanel</name>
    <message>
        <location filename="../../widgets/scene_panel.cpp" line="+84"/>
        <source>%1 or %2</source>
        <extracomment>uniform names, one of which a shader may declare: %1 the first ones, comma-separated; %2 the last</extracomment>
        <translation>%1 ou %2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Unused: the program on screen has no uniform %1 (a constant in the shader, perhaps), so this control changes nothing.

%2</source>
        <translation>Sem uso: o programa no ecrã não tem nenhum uniform %1 (uma constante no shader, talvez), por isso este controlo não altera nada.

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
        <translation>a mostrar N como cor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing light</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws L (towards the light) as a colour</extracomment>
        <translation>a mostrar L como cor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing view</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws V (towards the eye) as a colour</extracomment>
        <translation>a mostrar V como cor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing half</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws H, the half vector, as a colour</extracomment>
        <translation>a mostrar H como cor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing reflect</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws R, the reflected light, as a colour</extracomment>
        <translation>a mostrar R como cor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing ndotl</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws N·L as grey (&quot;ndotl&quot; is its name in files)</extracomment>
        <translation>a mostrar N·L em cinzento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>showing specular</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws the specular factor as grey</extracomment>
        <translation>a mostrar o fator especular em cinzento</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>showing attenuation</source>
        <comment>show</comment>
        <extracomment>status line: the built-in program draws a point light&apos;s attenuation as grey</extracomment>
        <translation>a mostrar a atenuação em cinzento</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>directional light in the camera frame</source>
        <translation>luz direcional no referencial da câmara</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the camera frame</source>
        <translation>luz pontual no referencial da câmara</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>directional light in the world frame</source>
        <translation>luz direcional no referencial do mundo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the world frame</source>
        <translation>luz pontual no referencial do mundo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>directional light in the object frame</source>
        <translation>luz direcional no referencial do objeto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point light in the object frame</source>
        <translation>luz pontual no referencial do objeto</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>%n light(s) on</source>
        <translation>
            <numerusform>%n luz ligada</numerusform>
            <numerusform>%n luzes ligadas</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the program&apos;s own light (marker hidden)</source>
        <translation>a luz própria do programa (marcador oculto)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Program: %1</source>
        <translation>Programa: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>drawn flat (per triangle)</source>
        <translation>desenhado com sombreamento plano (por triângulo)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 specular</source>
        <extracomment>%1 the specular model&apos;s name and cosine: &quot;Blinn-Phong (N·H)&quot;</extracomment>
        <translation>especular %1</translation>
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
        <translation>projeção perspetiva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>orthographic projection</source>
        <translation>projeção ortográfica</translation>
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
        <translation>%1 não é um ficheiro de definições</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 cannot be written</source>
        <translation>%1 não pode ser escrito</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Your work is saved again in %1</source>
        <translation>O seu trabalho volta a ser guardado em %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Your work is not saved, trying again every %1 s: %2</source>
        <translation>O seu trabalho não está guardado; nova tentativa a cada %1 s: %2</translation>
    </message>
</context>
<context>
    <name>lb::SettingsStore</name>
    <message>
        <location filename="../../app/window/settings_store.cpp" line="-24"/>
        <source>no temporary folder for the settings (%1): they are written directly</source>
        <translation>sem pasta temporária para as definições (%1): são escritas diretamente</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: cannot be written</source>
        <translation>%1: não pode ser escrito</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: its scratch copy %2 cannot be written (a full temporary folder?)</source>
        <translation>%1: a sua cópia temporária %2 não pode ser escrita (uma pasta temporária cheia?)</translation>
    </message>
</context>
<context>
    <name>lb::ShaderDocument</name>
    <message>
        <location filename="../../render/model/scene/shader_document.cpp" line="+204"/>
        <source>Cannot open %1</source>
        <translation>Não é possível abrir %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Cannot save %1</source>
        <translation>Não é possível guardar %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The shaders have no files yet: use Save As</source>
        <translation>Os shaders ainda não têm ficheiros: use Guardar Como</translation>
    </message>
</context>
<context>
    <name>lb::ShaderEditor</name>
    <message>
        <location filename="../../widgets/shader_editor.cpp" line="+137"/>
        <source>error: %1</source>
        <extracomment>a compiler&apos;s message under its line in the editor; %1 the message</extracomment>
        <translation>erro: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>warning: %1</source>
        <translation>aviso: %1</translation>
    </message>
</context>
<context>
    <name>lb::ShadingPanel</name>
    <message>
        <location filename="../../widgets/shading_panel.cpp" line="+27"/>
        <source>Gouraud (per vertex)</source>
        <translation>Gouraud (por vértice)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Phong (per fragment)</source>
        <translation>Phong (por fragmento)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flat (per triangle)</source>
        <translation>Plano (por triângulo)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gouraud: the model runs in the vertex shader and colours are interpolated; Phong: N, L, V are interpolated and the model runs for every fragment; flat: each triangle takes the colour of its last (provoking) vertex (key G: Gouraud / Phong)</source>
        <translation>Gouraud: o modelo corre no vertex shader e as cores são interpoladas; Phong: N, L, V são interpolados e o modelo corre para cada fragmento; plano: cada triângulo recebe a cor do seu último vértice (o provoking vertex) (tecla G: Gouraud / Phong)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Shading</source>
        <translation>Sombreamento</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>R = reflect(-L, N), the mirrored light direction; H = normalize(L + V), the half vector (key B)</source>
        <translation>R = reflect(-L, N), a direção da luz espelhada; H = normalize(L + V), o vetor médio (tecla B)</translation>
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
        <translation>Especular</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>Perspective: V = -posC</source>
        <translation>Perspetiva: V = -posC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Orthographic: V = (0,0,1)</source>
        <translation>Ortográfica: V = (0,0,1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mProjection, and the view vector V that matches it (key P)</source>
        <translation>mProjection, e o vetor de observação V que lhe corresponde (tecla P)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Projection</source>
        <translation>Projeção</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Colour (lit)</source>
        <extracomment>what the surface shows: the lit colour, or a vector (N, L, V, H, R) or number as colour</extracomment>
        <translation>Cor (iluminada)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>N as colour</source>
        <translation>N como cor</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>L as colour</source>
        <translation>L como cor</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>V as colour</source>
        <translation>V como cor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>H as colour</source>
        <translation>H como cor</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R as colour</source>
        <translation>R como cor</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>N·L as grey</source>
        <translation>N·L em cinzento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specular factor as grey</source>
        <translation>Fator especular em cinzento</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Attenuation as grey</source>
        <translation>Atenuação em cinzento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uShow: the model taken apart. Vectors as 0.5·v + 0.5 (x red, y green, z blue), numbers as grey; L, H, R and the numbers are light 1&apos;s (with several lights on too)</source>
        <translation>uShow: o modelo desmontado. Vetores como 0.5·v + 0.5 (x vermelho, y verde, z azul), números em cinzento; L, H, R e os números são os da luz 1 (também com várias luzes ligadas)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Show</source>
        <extracomment>the row of the Show choice (what the surface shows)</extracomment>
        <translation>Mostrar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Lighting</source>
        <extracomment>a switch: the lighting model on, or Kd unlit</extracomment>
        <translation>Iluminação</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>uEnableLighting: off shows Kd unlit (key L)</source>
        <translation>uEnableLighting: desligada mostra Kd sem iluminação (tecla L)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Vertex colours</source>
        <translation>Cores dos vértices</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Multiply ambient and diffuse by the vertex colour (vColor)</source>
        <translation>Multiplicar os termos ambiente e difuso pela cor do vértice (vColor)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ambient</source>
        <translation>Ambiente</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ia·Ka: uEnableAmbient (key A)</source>
        <translation>Ia·Ka: uEnableAmbient (tecla A)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diffuse</source>
        <translation>Difuso</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Id·Kd·max(N·L, 0): uEnableDiffuse (key D)</source>
        <translation>Id·Kd·max(N·L, 0): uEnableDiffuse (tecla D)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Is·Ks·(R·V or N·H)^n: uEnableSpecular (key S)</source>
        <translation>Is·Ks·(R·V ou N·H)^n: uEnableSpecular (tecla S)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Terms</source>
        <extracomment>the row of the ambient, diffuse and specular terms&apos; switches</extracomment>
        <translation>Termos</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Normals by the model-view (wrong)</source>
        <translation>Normais pela matriz model-view (errado)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transform normals by mModelView instead of its inverse transpose, to see why the normal matrix exists: under a non-uniform scale the normals tilt</source>
        <translation>Transformar as normais por mModelView em vez da sua transposta da inversa, para ver porque existe a matriz das normais: com uma escala não uniforme as normais inclinam-se</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Compare&lt;/b&gt; side A with side B</source>
        <translation>&lt;b&gt;Comparar&lt;/b&gt; o lado A com o lado B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Side A is the program on screen (the editor&apos;s); side B is the built-in program with the choices below, a shader pair from files, or an open exercise&apos;s reference; one camera</source>
        <translation>O lado A é o programa no ecrã (o do editor); o lado B é o programa integrado com as escolhas abaixo, um par de shaders de ficheiros ou a referência de um exercício aberto; uma só câmara</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Files...</source>
        <translation>Ficheiros...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B draws a shader pair from files (NAME.vert and NAME.frag), e.g. last week&apos;s solution</source>
        <translation>O lado B desenha um par de shaders de ficheiros (NAME.vert e NAME.frag), p. ex. a solução da semana passada</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop using these files: side B draws what it drew before them</source>
        <translation>Deixar de usar estes ficheiros: o lado B desenha o que desenhava antes deles</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>B program</source>
        <extracomment>the program side B of the compare view draws (A and B are the two sides)</extracomment>
        <translation>Programa B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Off</source>
        <extracomment>the compare view is off (A alone)</extracomment>
        <translation>Desligada</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Side by side</source>
        <translation>Lado a lado</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+34"/>
        <source>Wipe</source>
        <extracomment>the row of the slider that places the wipe&apos;s dividing line</extracomment>
        <translation>Cortina</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>Difference |A - B|</source>
        <translation>Diferença |A - B|</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side by side: A left, B right; wipe: drag the line in the view; difference: |A - B| as a heat map (key C cycles)</source>
        <translation>Lado a lado: A à esquerda, B à direita; cortina: arraste a linha na vista; diferença: |A - B| como mapa de calor (a tecla C alterna)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>View</source>
        <extracomment>the compare view (off, side by side, wipe, difference); not the menu, not the camera</extracomment>
        <translation>Vista</translation>
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
        <translation>B: Plano</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B&apos;s shading: per vertex or per fragment</source>
        <translation>O sombreamento do lado B: por vértice ou por fragmento</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>B shading</source>
        <extracomment>side B&apos;s shading (B is the compare view&apos;s second side)</extracomment>
        <translation>Sombreamento B</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B&apos;s specular term</source>
        <translation>O termo especular do lado B</translation>
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
        <translation>Especular B</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Where the wipe divides A (left) from B (right)</source>
        <translation>Onde a cortina separa A (esquerda) de B (direita)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reset shading</source>
        <translation>Repor sombreamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phong shading, Blinn-Phong specular, perspective, lighting on</source>
        <translation>Sombreamento de Phong, especular Blinn-Phong, perspetiva, iluminação ligada</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the built-in program</source>
        <translation>o programa integrado</translation>
    </message>
</context>
<context>
    <name>lb::Submission</name>
    <message>
        <location filename="../../app/common/submission.cpp" line="+72"/>
        <source>%1: a folder needs one NAME.vert and one NAME.frag (it has %2 and %3)</source>
        <translation>%1: uma pasta precisa de um NAME.vert e de um NAME.frag (tem %2 e %3)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: the scene file has no program</source>
        <translation>%1: o ficheiro de cena não tem programa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: the scene file&apos;s program cannot be used: %2</source>
        <extracomment>%2 why the scene&apos;s program was not used (&quot;program (the vertex shader has ... characters, ...)&quot;)</extracomment>
        <translation>%1: o programa do ficheiro de cena não pode ser usado: %2</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: no %2 beside it (a submission is NAME.vert and NAME.frag)</source>
        <translation>%1: não há nenhum %2 ao lado (uma submissão é NAME.vert e NAME.frag)</translation>
    </message>
</context>
<context>
    <name>lb::TextureControls</name>
    <message>
        <location filename="../../widgets/texture_controls.cpp" line="+28"/>
        <source>Texture</source>
        <translation>Textura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uEnableTexture: multiply ambient and diffuse by the texture (uSampler): the image file, else the mesh file&apos;s diffuse texture, else the checker</source>
        <translation>uEnableTexture: multiplicar os termos ambiente e difuso pela textura (uSampler): o ficheiro de imagem, senão a textura difusa do ficheiro da malha, senão o xadrez</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Image...</source>
        <translation>Imagem...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a PNG, JPEG or any image Qt reads as this object&apos;s texture (Ctrl+T, or drop it on the window); at most %1 x %1 texels</source>
        <translation>Abrir um PNG, JPEG ou qualquer imagem que o Qt leia como textura deste objeto (Ctrl+T, ou largue-a na janela); no máximo %1 x %1 texels</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No image: back to the mesh file&apos;s texture or the checker</source>
        <translation>Sem imagem: volta à textura do ficheiro da malha ou ao xadrez</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Repeat</source>
        <extracomment>texture wrapping: GL_REPEAT or GL_CLAMP_TO_EDGE</extracomment>
        <translation>Repetir</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Clamp</source>
        <translation>Limitar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Texture coordinates outside 0 to 1: the image repeats (GL_REPEAT) or its edge stretches (GL_CLAMP_TO_EDGE)</source>
        <translation>Coordenadas de textura fora de 0 a 1: a imagem repete-se (GL_REPEAT) ou a sua orla estende-se (GL_CLAMP_TO_EDGE)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Nearest</source>
        <extracomment>texture filtering: GL_NEAREST or GL_LINEAR</extracomment>
        <translation>Mais próximo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The texel nearest the coordinate (GL_NEAREST: blocky when magnified) or the four around it weighted (GL_LINEAR)</source>
        <translation>O texel mais próximo da coordenada (GL_NEAREST: em blocos quando ampliada) ou os quatro à sua volta, ponderados (GL_LINEAR)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Mipmaps</source>
        <translation>Mipmaps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where the texture is minified, read a smaller copy of it chosen by the level of detail (GL_NEAREST_MIPMAP_NEAREST, or trilinear GL_LINEAR_MIPMAP_LINEAR with the linear filter): no shimmer far away. The probe shows the level</source>
        <translation>Onde a textura é reduzida, ler uma cópia mais pequena dela escolhida pelo nível de detalhe (GL_NEAREST_MIPMAP_NEAREST, ou trilinear GL_LINEAR_MIPMAP_LINEAR com o filtro linear): sem cintilação ao longe. A sonda mostra o nível</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (not shown)</source>
        <translation>%1 (não mostrada)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the checker</source>
        <translation>o xadrez</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the mesh file&apos;s texture, or the checker</source>
        <translation>a textura do ficheiro da malha, ou o xadrez</translation>
    </message>
</context>
<context>
    <name>lb::TextureFile</name>
    <message>
        <location filename="../../render/model/scene/texture_file.cpp" line="+4"/>
        <source>%1: an empty file, not an image</source>
        <translation>%1: um ficheiro vazio, não uma imagem</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: not an image (%2)</source>
        <translation>%1: não é uma imagem (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the formats read are %1</source>
        <translation>os formatos lidos são %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 x %3 texels is more than a texture may have (%4 x %4)</source>
        <translation>%1: %2 x %3 texels é mais do que uma textura pode ter (%4 x %4)</translation>
    </message>
    <message>
        <location line="+30"/>
        <location line="+6"/>
        <source>%1: could not be read as an image: %2</source>
        <translation>%1: não foi possível ler como imagem: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2 x %3 texels (scaled from %4 x %5)</source>
        <extracomment>%1 a file&apos;s name, %2 x %3 the texels drawn, %4 x %5 the image&apos;s own size</extracomment>
        <translation>%1: %2 x %3 texels (redimensionado a partir de %4 x %5)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 x %3 texels</source>
        <translation>%1: %2 x %3 texels</translation>
    </message>
</context>
<context>
    <name>lb::TrialProcess</name>
    <message>
        <location filename="../../render/trial/trial_process.cpp" line="+167"/>
        <source>compiling this program and drawing it on small frames did not finish within %1 (the trial&apos;s helper was replaced): an endless or very long loop, or a program too big for the driver?</source>
        <translation>compilar este programa e desenhá-lo em fotogramas pequenos não terminou em %1 (o processo auxiliar de teste foi substituído): um ciclo infinito ou muito longo, ou um programa grande demais para o controlador?</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>the driver ran out of memory compiling or drawing this program (limit %1; the trial&apos;s helper was replaced)</source>
        <translation>o controlador ficou sem memória ao compilar ou desenhar este programa (limite %1; o processo auxiliar de teste foi substituído)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the driver crashed the trial&apos;s helper while it drew this program (it was replaced)</source>
        <translation>o controlador fez falhar o processo auxiliar de teste enquanto desenhava este programa (foi substituído)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the trial&apos;s helper ended while it drew this program (exit code %1; it was replaced)</source>
        <translation>o processo auxiliar de teste terminou enquanto desenhava este programa (código de saída %1; foi substituído)</translation>
    </message>
</context>
<context>
    <name>lb::UnfedInputs</name>
    <message>
        <location filename="../../render/glsl/unfed_inputs.cpp" line="+66"/>
        <source>the positions</source>
        <translation>as posições</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the normals</source>
        <translation>as normais</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the texture coordinates</source>
        <translation>as coordenadas de textura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the vertex colours</source>
        <translation>as cores dos vértices</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no array of the mesh</source>
        <translation>nenhum array da malha</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is at location %2, where the mesh gives %3, though its name says %4 (at location %5 here): write layout(location = %5) to read them</source>
        <extracomment>%1 the input&apos;s name; %2 its location; %3 what the mesh gives there; %4 what its name says; %5 the location that has it</extracomment>
        <translation>%1 está na location %2, onde a malha dá %3, embora o seu nome diga %4 (aqui na location %5): escreva layout(location = %5) para as ler</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>the scene feeds nothing to the matrix %1: it stays all zeros, and whatever it multiplies collapses to nothing on screen; bind it to one of %2 (the Bindings tab, or --bind %1=KEY)</source>
        <extracomment>%1 the uniform&apos;s name; %2 the keys it could be bound to (model-view, projection)</extracomment>
        <translation>a cena não alimenta a matriz %1: fica toda a zeros, e o que ela multiplica colapsa em nada no ecrã; ligue-a a um de %2 (o separador Ligações, ou --bind %1=KEY)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the scene feeds nothing to %1: it stays 0 unless you set it in the Uniforms panel; bind it to one of %2 (the Bindings tab, or --bind %1=KEY)</source>
        <extracomment>%1 the uniform&apos;s name; %2 the keys it could be bound to (light-position-world)</extracomment>
        <translation>a cena não alimenta %1: fica a 0 a menos que o defina no painel Uniforms; ligue-o a um de %2 (o separador Ligações, ou --bind %1=KEY)</translation>
    </message>
</context>
<context>
    <name>lb::UniformPanel</name>
    <message>
        <location filename="../../widgets/uniform_panel.cpp" line="+70"/>
        <source>The program has no uniforms of its own. A uniform that no panel feeds gets a control here.</source>
        <translation>O programa não tem uniforms próprios. Um uniform que nenhum painel alimenta recebe aqui um controlo.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The program&apos;s own uniforms; values stay when you recompile.</source>
        <translation>Os uniforms próprios do programa; os valores mantêm-se quando recompila.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No control for: %1 (matrices, samplers and arrays).</source>
        <extracomment>%1 the names of uniforms that get no control, comma-separated</extracomment>
        <translation>Sem controlo para: %1 (matrizes, samplers e arrays).</translation>
    </message>
</context>
<context>
    <name>lb::UnsavedWork</name>
    <message>
        <location filename="../../app/window/unsaved_work.cpp" line="+17"/>
        <source>the shader file %1</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation>o ficheiro de shader %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the shader files %1 and %2</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;; %1 and %2 are NAME.vert, NAME.frag</extracomment>
        <translation>os ficheiros de shader %1 e %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the lesson “%1”</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation>a lição “%1”</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the untitled scene</source>
        <extracomment>goes into &quot;Save the changes to %1 before ...?&quot;</extracomment>
        <translation>a cena sem título</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the scene “%1”</source>
        <translation>a cena “%1”</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 and %2</source>
        <extracomment>the lesson or the scene (%1) and the shader files (%2), in &quot;Save the changes to %1&quot;</extracomment>
        <translation>%1 e %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Save the changes to %1 before closing?</source>
        <translation>Guardar as alterações a %1 antes de fechar?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before opening “%2”?</source>
        <translation>Guardar as alterações a %1 antes de abrir “%2”?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before resetting everything?</source>
        <translation>Guardar as alterações a %1 antes de repor tudo?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the changes to %1 before closing it?</source>
        <translation>Guardar as alterações a %1 antes de a fechar?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the changes to %1 before starting a new lesson?</source>
        <translation>Guardar as alterações a %1 antes de começar uma nova lição?</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Your changes will be lost if you don&apos;t save them. Save saves them all.</source>
        <translation>As suas alterações perdem-se se não as guardar. Guardar guarda-as todas.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Your changes will be lost if you don&apos;t save them.</source>
        <translation>As suas alterações perdem-se se não as guardar.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Unsaved changes</source>
        <translation>Alterações por guardar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Discard</source>
        <translation>Descartar</translation>
    </message>
</context>
<context>
    <name>lb::ViewCoverage</name>
    <message>
        <location filename="../../render/model/measure/view_coverage.cpp" line="+86"/>
        <source>draws nothing in view: every face in view turns its back to the camera, and back faces are culled</source>
        <translation>não desenha nada à vista: todas as faces à vista voltam as costas à câmara, e as faces de trás são omitidas</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>is seen from behind: every face in view turns its back to the camera, lit as from behind (dark); Faces: Both sides lit shows that side lit</source>
        <translation>é visto por trás: todas as faces à vista voltam as costas à câmara, iluminadas como por trás (escuras); Faces: Ambos os lados iluminados mostra esse lado iluminado</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>draws nothing in view: it lies outside the view</source>
        <translation>não desenha nada à vista: está fora da vista</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>draws nothing in view: every face in view turns away from the camera and back faces are culled</source>
        <translation>não desenha nada à vista: todas as faces à vista estão viradas para longe da câmara e as faces de trás são omitidas</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>draws nothing in view: it is flat (in the %1 plane) and seen edge-on: turn it or the camera</source>
        <extracomment>%1: the plane the mesh lies in (YZ, XZ, XY)</extracomment>
        <translation>não desenha nada à vista: é plano (no plano %1) e visto de perfil: rode-o ou à câmara</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>draws nothing in view: it covers less than a pixel</source>
        <translation>não desenha nada à vista: cobre menos de um píxel</translation>
    </message>
</context>
<context>
    <name>lb::Viewport</name>
    <message>
        <location filename="../../widgets/viewport.cpp" line="+33"/>
        <source>Left drag: orbit - right or middle drag: pan - wheel: zoom - R: reset view</source>
        <translation>Arrastar com o botão esquerdo: orbitar - arrastar com o direito ou o do meio: deslocar - roda: zoom - R: repor a vista</translation>
    </message>
    <message>
        <location filename="../../render/pipeline/program_pipeline.cpp" line="+53"/>
        <source>the OpenGL context was lost while this program drew (the driver reset the GPU: an endless or very long loop?)</source>
        <translation>o contexto OpenGL perdeu-se enquanto este programa desenhava (o controlador reiniciou a GPU: um ciclo infinito ou muito longo?)</translation>
    </message>
    <message>
        <location filename="../../widgets/viewport.cpp" line="+94"/>
        <source>The renderer could not start:
%1</source>
        <translation>Não foi possível iniciar o renderizador:
%1</translation>
    </message>
    <message>
        <location filename="../../widgets/viewport_captions.cpp" line="+20"/>
        <source>The shader has errors (see the editor): the built-in program is drawing</source>
        <translation>O shader tem erros (ver o editor): o programa integrado está a desenhar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The shader has errors (see the editor): the last good program is drawing</source>
        <translation>O shader tem erros (ver o editor): o último programa válido está a desenhar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Refused: %1; the built-in program is drawing</source>
        <extracomment>%1 why the program was refused (a loop that never ends, a frame too slow)</extracomment>
        <translation>Recusado: %1; o programa integrado está a desenhar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Refused: %1; the last good program is drawing</source>
        <extracomment>%1 why the program was refused</extracomment>
        <translation>Recusado: %1; o último programa válido está a desenhar</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>OpenGL %1, %2; WebGL 1 shaders run as GLSL 3.30</source>
        <extracomment>%1 the OpenGL version (4.5); %2 the driver&apos;s renderer (llvmpipe ...)</extracomment>
        <translation>OpenGL %1, %2; os shaders WebGL 1 correm como GLSL 3.30</translation>
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
        <translation>o programa de referência</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B: built-in %1, %2</source>
        <extracomment>side B draws the built-in program: %1 its shading, %2 its specular term</extracomment>
        <translation>B: programa integrado %1, %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gouraud</source>
        <translation>Gouraud</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flat</source>
        <translation>plano</translation>
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
        <translation>A (esquerda): %1  |  %2 (direita)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+13"/>
        <source>the program on screen</source>
        <translation>o programa no ecrã</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>|A - B|: not drawn yet</source>
        <translation>|A - B|: ainda não desenhado</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>|A - B|, A: %7, %1: largest %2/255 at (%3, %4); %5% of the drawn pixels within %8/255; scale 0 (black) to %6/255 (white)</source>
        <translation>|A - B|, A: %7, %1: maior %2/255 em (%3, %4); %5% dos píxeis desenhados com diferença até %8/255; escala de 0 (preto) a %6/255 (branco)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (this view, %2 x %3 pixels); %4</source>
        <extracomment>%1 the difference view&apos;s figures; %2 x %3 the view&apos;s size in pixels; %4 what Check My Work measured for the case (its own frame size and figures)</extracomment>
        <translation>%1 (esta vista, %2 x %3 píxeis); %4</translation>
    </message>
</context>
<context>
    <name>lb::WireReader</name>
    <message>
        <location filename="../../render/import/wire_reader.cpp" line="+50"/>
        <source>the import stream goes on after its end</source>
        <translation>o fluxo de importação continua depois do seu fim</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the import helper wrote something that is not a mesh stream</source>
        <translation>o processo auxiliar de importação escreveu algo que não é um fluxo de malha</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the import stream holds two meshes</source>
        <translation>o fluxo de importação contém duas malhas</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the import stream announces a mesh of a bad size</source>
        <translation>o fluxo de importação anuncia uma malha de tamanho inválido</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the import stream holds a record too large to be right</source>
        <translation>o fluxo de importação contém um registo demasiado grande para ser válido</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>not enough memory for the mesh (%1 MB received)</source>
        <translation>memória insuficiente para a malha (%1 MB recebidos)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>receiving</source>
        <extracomment>a stage of loading a mesh file, shown beside its progress</extracomment>
        <translation>a receber</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the import stream holds an index past the last vertex</source>
        <translation>o fluxo de importação contém um índice para além do último vértice</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the import stream holds coordinates that are not finite</source>
        <translation>o fluxo de importação contém coordenadas não finitas</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the import stream announces a mesh whose sizes don&apos;t add up</source>
        <translation>o fluxo de importação anuncia uma malha cujos tamanhos não batem certo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the import stream announces a mesh of %1 MB, more than the helper may use (%2 MB)</source>
        <translation>o fluxo de importação anuncia uma malha de %1 MB, mais do que o processo auxiliar pode usar (%2 MB)</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>the import stream holds a short progress record</source>
        <translation>o fluxo de importação contém um registo de progresso incompleto</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the import failed without saying why</source>
        <translation>a importação falhou sem indicar o motivo</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the import stream holds a material of the wrong size</source>
        <translation>o fluxo de importação contém um material com o tamanho errado</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the import stream holds a short texture</source>
        <translation>o fluxo de importação contém uma textura incompleta</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the import stream holds a texture whose size doesn&apos;t add up</source>
        <translation>o fluxo de importação contém uma textura cujo tamanho não bate certo</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the import stream ended without a mesh</source>
        <translation>o fluxo de importação terminou sem uma malha</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the import stream holds a record of unknown type %1</source>
        <translation>o fluxo de importação contém um registo de tipo desconhecido %1</translation>
    </message>
</context>
<context>
    <name>lb::WorkCheck</name>
    <message>
        <location filename="../../app/common/work_check.cpp" line="+42"/>
        <source>killed by signal %1 (%2)</source>
        <extracomment>%2 is the C library&apos;s name of the signal, in English (&quot;Segmentation fault&quot;)</extracomment>
        <translation>terminado pelo sinal %1 (%2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exit code %1</source>
        <translation>código de saída %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>no temporary folder for the check: %1</source>
        <translation>sem pasta temporária para a verificação: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>your program</source>
        <translation>o seu programa</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>more than %1 s</source>
        <translation>mais de %1 s</translation>
    </message>
</context>
</TS>
