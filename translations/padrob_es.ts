<?xml version='1.0' encoding='utf-8'?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>AttemptLog</name>
    <message>
        <location filename="../trainer/training/attempt_log.cpp" line="+79" />
        <source>the records database is not open: this attempt is kept aside and recorded later</source>
        <translation>la base de datos de registros no está abierta: este intento se guarda aparte y se registra después</translation>
    </message>
    <message>
        <location line="+47" />
        <source>%1 — this attempt was saved in %2 and will be recorded when the database can be written</source>
        <translation>%1 — este intento se guardó en %2 y se registrará cuando se pueda escribir en la base de datos</translation>
    </message>
    <message>
        <location line="+46" />
        <source>cannot write %1</source>
        <translation>no se puede escribir %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>this attempt cannot be kept aside: %1</source>
        <translation>este intento no se puede guardar aparte: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 — and the attempt could not be saved aside either: %2</source>
        <translation>%1 — y tampoco se pudo guardar el intento aparte: %2</translation>
    </message>
    <message>
        <location line="+16" />
        <source>%1 is not a pending attempt (%2), and it cannot be moved aside</source>
        <translation>%1 no es un intento pendiente (%2), y no se puede apartar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not a pending attempt (%2): moved to %3</source>
        <translation>%1 no es un intento pendiente (%2): se movió a %3</translation>
    </message>
    <message>
        <location line="+30" />
        <source>not its format</source>
        <translation>no tiene su formato</translation>
    </message>
    <message>
        <location line="+36" />
        <location line="+7" />
        <source>it names no operator</source>
        <translation>no indica ningún operador</translation>
    </message>
</context>
<context>
    <name>CameraPath</name>
    <message>
        <location filename="../trainer/training/camera_path.cpp" line="+46" />
        <source>line %1: %2</source>
        <translation>línea %1: %2</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+15" />
        <source>not a camera path (the first line must be "%1")</source>
        <translation>no es una trayectoria de cámara (la primera línea debe ser "%1")</translation>
    </message>
    <message>
        <location line="-13" />
        <source>expected 7 numbers (t, target x y z, distance, yaw, pitch), found %1</source>
        <translation>se esperaban 7 números (t, objetivo x y z, distancia, guiñada, cabeceo), hay %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>"%1" is not a number</source>
        <translation>"%1" no es un número</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the time goes back</source>
        <translation>el tiempo retrocede</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the distance must be greater than 0</source>
        <translation>la distancia debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the pitch must be within ±π/2</source>
        <translation>el cabeceo debe estar dentro de ±π/2</translation>
    </message>
</context>
<context>
    <name>CentreBus</name>
    <message>
        <location filename="../trainer/centre/bus.cpp" line="+172" />
        <source>A %1 message was not sent: its field %2.</source>
        <translation>No se envió un mensaje %1: su campo %2.</translation>
    </message>
    <message>
        <location line="+87" />
        <source>The centre's DDS domain must be a number from 0 to 232 (it is %1).</source>
        <translation>El dominio DDS del centro debe ser un número de 0 a 232 (es %1).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>DDS Security needs this node's name (--name), made of letters, digits and - _ . @, not '%1'.</source>
        <translation>DDS Security necesita el nombre de este nodo (--name), hecho de letras, dígitos y - _ . @, no '%1'.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>DDS Security covers the domains 0 to 230: choose one of them for the centre (it is %1).</source>
        <translation>DDS Security abarca los dominios 0 a 230: elija uno de ellos para el centro (es %1).</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Could not join the centre's network (DDS domain %1): %2. Check the centre's network interfaces and peers.</source>
        <translation>No se pudo entrar a la red del centro (dominio DDS %1): %2. Revise las interfaces de red y los pares del centro.</translation>
    </message>
    <message>
        <location line="+19" />
        <source>DDS Security refused node %1's identity or permissions in %2 (%3). Check that the node's files and the centre's identity_ca.pem, permissions_ca.pem and governance.p7s come from the same 'padrob centre pki', and that the security plugins of Cyclone DDS are installed.</source>
        <translation>DDS Security rechazó la identidad o los permisos del nodo %1 en %2 (%3). Revise que los archivos del nodo y los identity_ca.pem, permissions_ca.pem y governance.p7s del centro vengan del mismo 'padrob centre pki', y que los complementos de seguridad de Cyclone DDS estén instalados.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Could not join the centre's network (DDS domain %1): %2.</source>
        <translation>No se pudo entrar a la red del centro (dominio DDS %1): %2.</translation>
    </message>
    <message>
        <location line="+35" />
        <location line="+12" />
        <source>Could not create the centre's topic %1: %2.</source>
        <translation>No se pudo crear el tópico %1 del centro: %2.</translation>
    </message>
</context>
<context>
    <name>CentreKey</name>
    <message>
        <location filename="../trainer/centre/signing.cpp" line="+192" />
        <source>Cannot read the centre's key file %1: %2.</source>
        <translation>No se puede leer el archivo de clave del centro %1: %2.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The centre's key file %1 can be read by other users: make it readable by its owner only (chmod 600 %1).</source>
        <translation>El archivo de clave del centro %1 lo pueden leer otros usuarios: déjelo legible solo por su dueño (chmod 600 %1).</translation>
    </message>
    <message>
        <location line="+15" />
        <source>The node key file %1 must name its node on its first line ('%2 NAME', a name of at most %3 bytes without spaces); make one with 'padrob centre key --key CENTRE-KEY --node NAME FILE'.</source>
        <translation>El archivo de clave de nodo %1 debe nombrar su nodo en su primera línea ('%2 NOMBRE', un nombre de a lo más %3 bytes sin espacios); cree uno con 'padrob centre key --key CLAVE-DEL-CENTRO --node NOMBRE ARCHIVO'.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>The centre's key file %1 must hold 64 hexadecimal digits (32 bytes); make one with 'padrob centre key FILE'.</source>
        <translation>El archivo de clave del centro %1 debe contener 64 dígitos hexadecimales (32 bytes); cree uno con 'padrob centre key ARCHIVO'.</translation>
    </message>
    <message>
        <location line="+16" />
        <source>%1 exists already: a centre's key is never overwritten.</source>
        <translation>%1 ya existe: la clave de un centro nunca se sobrescribe.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Cannot write the centre's key file %1: %2.</source>
        <translation>No se puede escribir el archivo de clave del centro %1: %2.</translation>
    </message>
    <message>
        <location line="+18" />
        <source>A node's key is made from the centre's key, not from another node's key.</source>
        <translation>La clave de un nodo se crea a partir de la clave del centro, no de la clave de otro nodo.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>A node's name has 1 to %1 bytes and no spaces.</source>
        <translation>El nombre de un nodo tiene de 1 a %1 bytes y no lleva espacios.</translation>
    </message>
    <message>
        <location line="+63" />
        <source>%1 is node %2's key, not %3's: give %3 its own (padrob centre key --key CENTRE-KEY --node %3 FILE) or the centre's key.</source>
        <translation>%1 es la clave del nodo %2, no la de %3: dé a %3 la suya (padrob centre key --key CLAVE-DEL-CENTRO --node %3 ARCHIVO) o la clave del centro.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1 is node %2's key: an instructor needs the centre's key, which signs the commands for every station and checks what each says.</source>
        <translation>%1 es la clave del nodo %2: un instructor necesita la clave del centro, que firma las órdenes para cada estación y verifica lo que cada una dice.</translation>
    </message>
</context>
<context>
    <name>CentrePki</name>
    <message>
        <location filename="../trainer/centre/pki.cpp" line="+51" />
        <source>%1 exists already: a PKI file is never replaced (remove it first if you mean to).</source>
        <translation>%1 ya existe: un archivo de la PKI nunca se reemplaza (bórrelo antes si es lo que quiere).</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Could not write %1: %2.</source>
        <translation>No se pudo escribir %1: %2.</translation>
    </message>
    <message>
        <location line="+160" />
        <source>OpenSSL could not make %1.</source>
        <translation>OpenSSL no pudo crear %1.</translation>
    </message>
    <message>
        <location line="+20" />
        <source>%1 holds a centre's PKI already: it is never replaced.</source>
        <translation>%1 ya contiene la PKI de un centro: nunca se reemplaza.</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+48" />
        <source>Could not make the folder %1.</source>
        <translation>No se pudo crear la carpeta %1.</translation>
    </message>
    <message>
        <location line="-43" />
        <source>the CAs' keys</source>
        <translation>las claves de las CA</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the CAs' certificates</source>
        <translation>los certificados de las CA</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the signed governance document</source>
        <translation>el documento de gobernanza firmado</translation>
    </message>
    <message>
        <location line="+14" />
        <source>'%1' cannot be a node's name in the centre's PKI: use letters, digits and - _ . @ (up to 64).</source>
        <translation>'%1' no puede ser el nombre de un nodo en la PKI del centro: use letras, dígitos y - _ . @ (hasta 64).</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 has no centre PKI (identity_ca.pem/.key, permissions_ca.pem/.key): make it with 'padrob centre pki %1'.</source>
        <translation>%1 no tiene PKI del centro (identity_ca.pem/.key, permissions_ca.pem/.key): créela con 'padrob centre pki %1'.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Node %1 has an identity already in %2: it is never replaced.</source>
        <translation>El nodo %1 ya tiene una identidad en %2: nunca se reemplaza.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>the node's certificate</source>
        <translation>el certificado del nodo</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the signed permissions document</source>
        <translation>el documento de permisos firmado</translation>
    </message>
    <message>
        <location line="+18" />
        <source>DDS Security: %1 is missing. Issue this node's identity with 'padrob centre pki %2 --node %3' on the computer that holds the centre's PKI, and copy the files here.</source>
        <translation>DDS Security: falta %1. Emita la identidad de este nodo con 'padrob centre pki %2 --node %3' en el computador que guarda la PKI del centro, y copie aquí los archivos.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>DDS Security: %1 is not a certificate. Copy the centre's identity_ca.pem again.</source>
        <translation>DDS Security: %1 no es un certificado. Copie de nuevo el identity_ca.pem del centro.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>DDS Security: %1 is not a certificate. Issue this node's identity again with 'padrob centre pki %2 --node %3'.</source>
        <translation>DDS Security: %1 no es un certificado. Emita de nuevo la identidad de este nodo con 'padrob centre pki %2 --node %3'.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>DDS Security: %1 was not issued by this centre's identity CA (%2). Issue this node's identity with 'padrob centre pki DIR --node %3' using the centre's PKI.</source>
        <translation>DDS Security: %1 no lo emitió la CA de identidad de este centro (%2). Emita la identidad de este nodo con 'padrob centre pki CARPETA --node %3' usando la PKI del centro.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>DDS Security: %1 is not valid now (expired, or this computer's clock is wrong). Check the clock, or issue a new identity for the node.</source>
        <translation>DDS Security: %1 no es válido ahora (venció, o el reloj de este computador está mal). Revise el reloj, o emita una nueva identidad para el nodo.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>DDS Security: %1 is not the private key of %2. Copy the node's folder again.</source>
        <translation>DDS Security: %1 no es la clave privada de %2. Copie de nuevo la carpeta del nodo.</translation>
    </message>
</context>
<context>
    <name>Diagnostics</name>
    <message>
        <location filename="../ide/studio/editor/diagnostic_text.cpp" line="+23" />
        <location line="+4" />
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <location line="-3" />
        <source>Warning</source>
        <translation>Advertencia</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <location line="+76" />
        <source>Hint:</source>
        <translation>Sugerencia:</translation>
    </message>
    <message>
        <location filename="../ide/i18n/diagnostic_text.cpp" line="+31" />
        <location line="+4" />
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <location line="-3" />
        <source>warning</source>
        <translation>advertencia</translation>
    </message>
    <message>
        <location line="+1" />
        <source>note</source>
        <translation>nota</translation>
    </message>
    <message>
        <location filename="../solver/core/diagnostic.cpp" line="+131" />
        <source>too many problems; the rest are not listed</source>
        <translation>demasiados problemas; el resto no se muestra</translation>
    </message>
    <message>
        <location line="+1" />
        <source>fix the ones above first</source>
        <translation>corrija primero los de arriba</translation>
    </message>
    <message>
        <location filename="../solver/inertia/solid_inertia.cpp" line="+68" />
        <location line="+131" />
        <location filename="../solver/parse/parser.cpp" line="+1412" />
        <location filename="../solver/spec/validate.cpp" line="+510" />
        <location line="+107" />
        <source>graphic %1</source>
        <translation>gráfico %1</translation>
    </message>
    <message>
        <location line="-125" />
        <location filename="../solver/spec/validate.cpp" line="-53" />
        <source>%1: mesh file '%2' not found (looked for %3)</source>
        <translation>%1: no se encontró el archivo de malla '%2' (se buscó %3)</translation>
    </message>
    <message>
        <location line="+4" />
        <location filename="../solver/spec/validate.cpp" line="+4" />
        <source>mesh paths are relative to the model file's folder</source>
        <translation>las rutas de las mallas son relativas a la carpeta del archivo de modelo</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: mesh file '%2' cannot be read: %3</source>
        <translation>%1: no se puede leer el archivo de malla '%2': %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>export the mesh again (STL, OBJ, PLY, …) or check that the file is not damaged</source>
        <translation>exporte la malla de nuevo (STL, OBJ, PLY, …) o revise que el archivo no esté dañado</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the mesh is not closed: %2 open edges</source>
        <translation>%1: la malla no es cerrada: %2 aristas abiertas</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a solid's surface must be watertight (every edge joins two triangles); close its holes in a mesh editor</source>
        <translation>la superficie de un sólido debe ser estanca (cada arista une dos triángulos); cierre sus agujeros en un editor de mallas</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the mesh's faces are not consistently oriented: %2 edges</source>
        <translation>%1: las caras de la malla no tienen una orientación coherente: %2 aristas</translation>
    </message>
    <message>
        <location line="+3" />
        <source>recalculate the normals in a mesh editor so they all point outwards</source>
        <translation>recalcule las normales en un editor de mallas para que todas apunten hacia afuera</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1: the mesh encloses no volume</source>
        <translation>%1: la malla no encierra ningún volumen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a solid needs a closed surface around a volume</source>
        <translation>un sólido necesita una superficie cerrada alrededor de un volumen</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: the mesh's normals point inwards (negative volume); its absolute value is used</source>
        <translation>%1: las normales de la malla apuntan hacia adentro (volumen negativo); se usa su valor absoluto</translation>
    </message>
    <message>
        <location line="+2" />
        <source>flip the normals in a mesh editor</source>
        <translation>invierta las normales en un editor de mallas</translation>
    </message>
    <message>
        <location line="+78" />
        <source>%1: MASS is negative</source>
        <translation>%1: el valor de MASS es negativo</translation>
    </message>
    <message>
        <location line="+1" />
        <location filename="../solver/spec/validate.cpp" line="+19" />
        <source>a mass is ≥ 0, in kg</source>
        <translation>una masa es ≥ 0, en kg</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: RHO must be positive</source>
        <translation>%1: el valor de RHO debe ser positivo</translation>
    </message>
    <message>
        <location line="+1" />
        <location filename="../solver/spec/validate.cpp" line="+4" />
        <source>a density in kg/m³ (steel: 7850)</source>
        <translation>una densidad en kg/m³ (acero: 7850)</translation>
    </message>
    <message>
        <location filename="../solver/collision/collision_world.cpp" line="+114" />
        <source>G %1 is left out of the clearance checks: %2</source>
        <translation>G %1 queda fuera de los controles de distancia libre: %2</translation>
    </message>
    <message>
        <location filename="../solver/compile/compile.cpp" line="+228" />
        <location filename="../solver/compile/initial_configuration.cpp" line="+44" />
        <location line="+9" />
        <location filename="../solver/compile/topology.cpp" line="+39" />
        <location filename="../solver/parse/parser.cpp" line="-551" />
        <location line="+135" />
        <location filename="../solver/spec/validate.cpp" line="-558" />
        <location line="+582" />
        <source>joint %1</source>
        <translation>articulación %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the drive on %1 cannot act: the joint closes a loop, so it is a constraint, not a coordinate</source>
        <translation>el accionamiento de la %1 no puede actuar: la articulación cierra un lazo, así que es una restricción, no una coordenada</translation>
    </message>
    <message>
        <location line="+2" />
        <source>move the drive to another joint of the loop, or leave one joint of the loop passive</source>
        <translation>pase el accionamiento a otra articulación del lazo, o deje pasiva una articulación del lazo</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 closes a loop: its limits LL/UL are not enforced</source>
        <translation>la %1 cierra un lazo: sus límites LL/UL no se aplican</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put the limits on another joint of the loop (a tree joint)</source>
        <translation>ponga los límites en otra articulación del lazo (una articulación del árbol)</translation>
    </message>
    <message>
        <location filename="../solver/compile/initial_configuration.cpp" line="+3" />
        <source>joints %1 and %2</source>
        <translation>articulaciones %1 y %2</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../solver/compile/topology.cpp" line="-14" />
        <location filename="../solver/integrate/simulation.cpp" line="+55" />
        <location filename="../solver/parse/parser.cpp" line="-200" />
        <location filename="../solver/spec/validate.cpp" line="-589" />
        <location line="+588" />
        <source>body %1</source>
        <translation>cuerpo %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 is not connected to ground: no chain of joints leads from body 0 to it</source>
        <translation>el %1 no está conectado a tierra: ninguna cadena de articulaciones lo une con el cuerpo 0</translation>
    </message>
    <message>
        <location line="+2" />
        <source>add a joint (C) that connects it to ground or to a connected body</source>
        <translation>agregue una articulación (C) que lo conecte a tierra o a un cuerpo conectado</translation>
    </message>
    <message>
        <location line="+24" />
        <source>%1 is a free joint (T 3), but its body B2 is also held by other joints (a closed loop)</source>
        <translation>la %1 es una articulación libre (T 3), pero su cuerpo B2 también lo sujetan otras articulaciones (un lazo cerrado)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a free body moves only through its free joint: remove the other joints between it and the rest, or use T 0, T 1 or T 2</source>
        <translation>un cuerpo libre se mueve solo por su articulación libre: quite las otras articulaciones entre él y el resto, o use T 0, T 1 o T 2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 is a free joint (T 3) whose B2 is nearer the ground than its B1</source>
        <translation>la %1 es una articulación libre (T 3) cuyo B2 está más cerca de tierra que su B1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>write the free joint from the side nearer the ground (B1, usually body 0) to the free body (B2)</source>
        <translation>escriba la articulación libre desde el lado más cercano a tierra (B1, normalmente el cuerpo 0) hacia el cuerpo libre (B2)</translation>
    </message>
    <message>
        <location filename="../solver/compile/initial_configuration.cpp" line="+17" />
        <source>joint %1's actuator</source>
        <translation>actuador de la articulación %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 keeps the same length %2 m whatever the joint angle: CL1 or CL2 lies on the joint axis A, so the actuator cannot turn the joint</source>
        <translation>el %1 mantiene la misma longitud de %2 m cualquiera sea el ángulo de la articulación: CL1 o CL2 está sobre el eje A de la articulación, así que el actuador no puede hacerla girar</translation>
    </message>
    <message>
        <location line="+4" />
        <source>place CL1 (on body %1) and CL2 (on body %2) away from the joint axis, so that the actuator length changes as the joint turns</source>
        <translation>ubique CL1 (en el cuerpo %1) y CL2 (en el cuerpo %2) fuera del eje de la articulación, de modo que la longitud del actuador cambie al girar la articulación</translation>
    </message>
    <message>
        <location line="+21" />
        <source>the actuator length |CL2 − CL1| goes from %1 m to %2 m as the joint turns; choose %3 within that range, or check CL1, CL2 and the joint points P1, P2 (a reachable QI is taken at the joint angle nearest to 0)</source>
        <translation>la longitud del actuador |CL2 − CL1| va de %1 m a %2 m al girar la articulación; elija %3 dentro de ese rango, o revise CL1, CL2 y los puntos P1, P2 de la articulación (un QI alcanzable se toma en el ángulo de la articulación más cercano a 0)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the actuator length |CL2 − CL1| goes from %1 m to %2 m as the joint turns; choose %3 within that range, or check CL1, CL2 and the joint points P1, P2</source>
        <translation>la longitud del actuador |CL2 − CL1| va de %1 m a %2 m al girar la articulación; elija %3 dentro de ese rango, o revise CL1, CL2 y los puntos P1, P2 de la articulación</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 = %2 m is beyond the reach of %3 (%4 m .. %5 m)</source>
        <translation>%1 = %2 m está fuera del alcance del %3 (%4 m .. %5 m)</translation>
    </message>
    <message>
        <location line="+28" />
        <source>longest</source>
        <translation>máxima</translation>
    </message>
    <message>
        <location line="+1" />
        <source>shortest</source>
        <translation>mínima</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 reaches a dead point inside its stroke: its length is %2 (%3 m) at joint angle %4 rad, and no %5 stops it before</source>
        <translation>el %1 pasa por un punto muerto dentro de su carrera: su longitud es %2 (%3 m) con un ángulo de articulación de %4 rad, y ningún %5 lo detiene antes</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 reaches a dead point inside its stroke: its length is %2 (%3 m) at joint angle %4 rad, between LL and UL</source>
        <translation>el %1 pasa por un punto muerto dentro de su carrera: su longitud es %2 (%3 m) con un ángulo de articulación de %4 rad, entre LL y UL</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the cylinder cannot drive the joint through that point (dL/dθ = 0 there); set %1 below %2 m</source>
        <translation>el cilindro no puede mover la articulación a través de ese punto (ahí dL/dθ = 0); fije %1 por debajo de %2 m</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the cylinder cannot drive the joint through that point (dL/dθ = 0 there); set %1 above %2 m</source>
        <translation>el cilindro no puede mover la articulación a través de ese punto (ahí dL/dθ = 0); fije %1 por encima de %2 m</translation>
    </message>
    <message>
        <location line="+104" />
        <source>P2 lies %1 m off the sliding line through P1</source>
        <translation>P2 queda a %1 m de la línea de deslizamiento que pasa por P1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>P1 and P2 stay %1 m apart</source>
        <translation>P1 y P2 quedan a %1 m uno del otro</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the joint frames are turned by about %1 rad</source>
        <translation>los sistemas de referencia de la articulación están girados unos %1 rad</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the axes A1 and A2 are %1 rad out of line</source>
        <translation>los ejes A1 y A2 están desalineados %1 rad</translation>
    </message>
    <message>
        <location line="+12" />
        <source>check the joint points P1, P2 and the link lengths of the loop</source>
        <translation>revise los puntos P1, P2 de las articulaciones y las longitudes de los eslabones del lazo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>check the joint points P1, P2 and the link lengths of the loop, and the QI of its independent coordinates (%1)</source>
        <translation>revise los puntos P1, P2 de las articulaciones y las longitudes de los eslabones del lazo, y el QI de sus coordenadas independientes (%1)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the loop closed by %1 cannot be assembled at the initial configuration: its closure equations keep a residual of %2</source>
        <translation>el lazo que cierra la %1 no se puede armar en la configuración inicial: sus ecuaciones de cierre mantienen un residuo de %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the loop closed by %1 cannot be assembled at the initial configuration: its closure equations keep a residual of %2 (%3)</source>
        <translation>el lazo que cierra la %1 no se puede armar en la configuración inicial: sus ecuaciones de cierre mantienen un residuo de %2 (%3)</translation>
    </message>
    <message>
        <location line="+21" />
        <location line="+249" />
        <source>give the bodies it moves a mass (B id m Ixx Iyy Izz), or remove the joint</source>
        <translation>dé masa a los cuerpos que mueve (B id m Ixx Iyy Izz), o elimine la articulación</translation>
    </message>
    <message>
        <location line="-228" />
        <source>the bodies it moves have no mass</source>
        <translation>los cuerpos que mueve no tienen masa</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+225" />
        <source>the bodies it moves have no mass, or only mass on its axis and no inertia about it</source>
        <translation>los cuerpos que mueve no tienen masa, o solo tienen masa sobre su eje y ninguna inercia respecto de él</translation>
    </message>
    <message>
        <location line="-222" />
        <location line="+219" />
        <source>%1 moves no mass: %2, so the mass matrix is singular at the initial configuration</source>
        <translation>la %1 no mueve masa: %2, así que la matriz de masa es singular en la configuración inicial</translation>
    </message>
    <message>
        <location line="-215" />
        <source>%1 and the loop it drives (%2) move no mass: %3, so the mass matrix is singular at the initial configuration</source>
        <translation>la %1 y el lazo que acciona (%2) no mueven masa: %3, así que la matriz de masa es singular en la configuración inicial</translation>
    </message>
    <message>
        <location line="+31" />
        <source>%1 for joint %2</source>
        <translation>%1 para la articulación %2</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1 together move no mass: the motion with rates %2 leaves every body with mass at rest, so the mass matrix is singular at the initial configuration</source>
        <translation>las %1 en conjunto no mueven masa: el movimiento con velocidades %2 deja en reposo todos los cuerpos con masa, así que la matriz de masa es singular en la configuración inicial</translation>
    </message>
    <message>
        <location filename="../solver/core/text_file.cpp" line="+20" />
        <source>give the path of a %1 file</source>
        <translation>indique la ruta de un archivo %1</translation>
    </message>
    <message>
        <location line="+3" />
        <location filename="../solver/inertia/triangle_mesh.cpp" line="+88" />
        <source>no such file</source>
        <translation>el archivo no existe</translation>
    </message>
    <message>
        <location line="+0" />
        <source>check the path</source>
        <translation>revise la ruta</translation>
    </message>
    <message>
        <location line="+1" />
        <source>this is a folder, not %1</source>
        <translation>esto es una carpeta, no %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>this is not a regular file</source>
        <translation>este no es un archivo normal</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the file is too large for %1 (%2 MB; the limit is %3 MB)</source>
        <translation>el archivo es demasiado grande para %1 (%2 MB; el límite es %3 MB)</translation>
    </message>
    <message>
        <location line="+10" />
        <source>cannot be read (permission denied?)</source>
        <translation>no se puede leer (¿permiso denegado?)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>check the file's permissions</source>
        <translation>revise los permisos del archivo</translation>
    </message>
    <message>
        <location line="+11" />
        <source>reading failed</source>
        <translation>falló la lectura</translation>
    </message>
    <message>
        <location line="+0" />
        <source>check the disk and the file's permissions</source>
        <translation>revise el disco y los permisos del archivo</translation>
    </message>
    <message>
        <location filename="../solver/inertia/triangle_mesh.cpp" line="+6" />
        <source>the file holds no scene</source>
        <translation>el archivo no contiene ninguna escena</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the file holds no triangles</source>
        <translation>el archivo no contiene triángulos</translation>
    </message>
    <message>
        <location filename="../solver/io/input_table.cpp" line="+144" />
        <source>%1: the value has no closing quote</source>
        <translation>%1: el valor no tiene comilla de cierre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>close the quote, or write the number without quotes</source>
        <translation>cierre la comilla, o escriba el número sin comillas</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: no value</source>
        <translation>%1: no hay valor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a number (0 for a closed valve)</source>
        <translation>escriba un número (0 para una válvula cerrada)</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+16" />
        <location filename="../solver/parse/parser.cpp" line="-536" />
        <location line="+9" />
        <source>%1: '%2' is not a number</source>
        <translation>%1: '%2' no es un número</translation>
    </message>
    <message>
        <location line="-15" />
        <location filename="../solver/parse/parser.cpp" line="-8" />
        <source>use '.' as the decimal separator: %1</source>
        <translation>use '.' como separador decimal: %1</translation>
    </message>
    <message>
        <location line="+5" />
        <location filename="../solver/parse/parser.cpp" line="+2" />
        <source>%1: '%2' is not a finite number</source>
        <translation>%1: '%2' no es un número finito</translation>
    </message>
    <message>
        <location line="+1" />
        <location filename="../solver/parse/parser.cpp" line="+1" />
        <source>write a finite value; NaN and infinity are not allowed</source>
        <translation>escriba un valor finito; no se permiten NaN ni infinito</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: '%2' is too large</source>
        <translation>%1: '%2' es demasiado grande</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a value that fits a double (below 1.8e308)</source>
        <translation>escriba un valor que quepa en un double (menor que 1.8e308)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>write a number in the C locale: '.' as the decimal point, e.g. -0.25 or 1e-3</source>
        <translation>escriba el número en la configuración regional C: '.' como punto decimal, p. ej. -0.25 o 1e-3</translation>
    </message>
    <message>
        <location line="+66" />
        <source>the input file is empty</source>
        <translation>el archivo de entradas está vacío</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a header naming the columns, then one row per time, e.g. t,u2 then 0,0.5</source>
        <translation>escriba un encabezado que nombre las columnas y luego una fila por instante, p. ej. t,u2 y luego 0,0.5</translation>
    </message>
    <message>
        <location line="+22" />
        <source>the column name has no closing quote</source>
        <translation>el nombre de la columna no tiene comilla de cierre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>close the quote, or write the name without quotes</source>
        <translation>cierre la comilla, o escriba el nombre sin comillas</translation>
    </message>
    <message>
        <location line="+5" />
        <source>column %1 has no name</source>
        <translation>la columna %1 no tiene nombre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>name every column: t for the time, u&lt;joint id&gt; for a command (e.g. u2)</source>
        <translation>nombre cada columna: t para el tiempo, u&lt;id de articulación&gt; para un comando (p. ej. u2)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>column 't' appears twice (first at column %1)</source>
        <translation>la columna 't' aparece dos veces (primero en la columna %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+16" />
        <source>remove one of them</source>
        <translation>elimine una de ellas</translation>
    </message>
    <message>
        <location line="-5" />
        <source>column '%1' is joint %2's command again ('%3' at column %4)</source>
        <translation>la columna '%1' repite el comando de la articulación %2 ('%3' en la columna %4)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>'%1' is not an input column name</source>
        <translation>'%1' no es un nombre de columna de entrada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>name the time column t and each command column u&lt;joint id&gt;, e.g. u2</source>
        <translation>nombre t la columna del tiempo y u&lt;id de articulación&gt; cada columna de comando, p. ej. u2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the header has no 't' column</source>
        <translation>el encabezado no tiene columna 't'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the first line names the columns: t, then u&lt;joint id&gt; for each command, e.g. t,u2</source>
        <translation>la primera línea nombra las columnas: t y luego u&lt;id de articulación&gt; para cada comando, p. ej. t,u2</translation>
    </message>
    <message>
        <location line="+19" />
        <source>this row has %1 value; the header names %2 columns</source>
        <translation>esta fila tiene %1 valor; el encabezado nombra %2 columnas</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+7" />
        <source>this row has %1 values; the header names %2 columns</source>
        <translation>esta fila tiene %1 valores; el encabezado nombra %2 columnas</translation>
    </message>
    <message>
        <location line="-4" />
        <source>give a value for every column (0 for a closed valve)</source>
        <translation>indique un valor para cada columna (0 para una válvula cerrada)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>this row has %1 values; the header names %2 column</source>
        <translation>esta fila tiene %1 valores; el encabezado nombra %2 columna</translation>
    </message>
    <message>
        <location line="+5" />
        <source>one value per column; if ',' is a decimal separator here, write '.' instead (0.5, not 0,5)</source>
        <translation>un valor por columna; si aquí ',' es un separador decimal, escriba '.' en su lugar (0.5, no 0,5)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>one value per column, separated by %1</source>
        <translation>un valor por columna, separados por %1</translation>
    </message>
    <message>
        <location line="+9" />
        <source>time</source>
        <translation>tiempo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>column '%1'</source>
        <translation>columna '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>column %1</source>
        <translation>columna %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>time %1 repeats the time of line %2</source>
        <translation>el tiempo %1 repite el tiempo de la línea %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>time %1 comes after time %2 (line %3); times must increase</source>
        <translation>el tiempo %1 viene después del tiempo %2 (línea %3); los tiempos deben ser crecientes</translation>
    </message>
    <message>
        <location line="+5" />
        <source>sort the rows by time, each time once</source>
        <translation>ordene las filas por tiempo, cada tiempo una sola vez</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: %2 is outside [-1, 1]</source>
        <translation>%1: %2 está fuera de [-1, 1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a command is a valve spool position (or joystick axis) from -1 to 1</source>
        <translation>un comando es una posición de la corredera de la válvula (o un eje del joystick) de -1 a 1</translation>
    </message>
    <message>
        <location line="+20" />
        <source>the input file has a header but no rows</source>
        <translation>el archivo de entradas tiene encabezado pero no tiene filas</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add one row per time under the header, e.g. 0,0.5</source>
        <translation>agregue una fila por instante bajo el encabezado, p. ej. 0,0.5</translation>
    </message>
    <message>
        <location line="+11" />
        <source>an input file</source>
        <translation>un archivo de entradas</translation>
    </message>
    <message>
        <location line="+1" />
        <source>split the session, or record the commands less often</source>
        <translation>divida la sesión, o grabe los comandos con menor frecuencia</translation>
    </message>
    <message>
        <location line="+60" />
        <source>column '%1': the model has no joint %2</source>
        <translation>columna '%1': el modelo no tiene la articulación %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the model has no drives; remove the column</source>
        <translation>el modelo no tiene accionamientos; elimine la columna</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the joints with a drive are %1</source>
        <translation>las articulaciones con accionamiento son %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>column '%1': joint %2 has no drive</source>
        <translation>columna '%1': la articulación %2 no tiene accionamiento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a command moves a drive: remove the column, or give the joint a drive (D %1 …)</source>
        <translation>un comando mueve un accionamiento: elimine la columna, o dé un accionamiento a la articulación (D %1 …)</translation>
    </message>
    <message>
        <location line="+17" />
        <source>no column for joint %1's drive</source>
        <translation>no hay columna para el accionamiento de la articulación %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no columns for the drives of joints %1</source>
        <translation>no hay columnas para los accionamientos de las articulaciones %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the table has one column u&lt;joint id&gt; per drive; write 0 in a column to keep that valve closed</source>
        <translation>la tabla tiene una columna u&lt;id de articulación&gt; por accionamiento; escriba 0 en una columna para mantener esa válvula cerrada</translation>
    </message>
    <message>
        <location filename="../solver/pipeline.cpp" line="+94" />
        <source>this is not a text file (it contains a NUL byte here)</source>
        <translation>este no es un archivo de texto (contiene un byte NUL aquí)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+10" />
        <source>a model is a text file (.pad); open the model, not a mesh, image or archive</source>
        <translation>un modelo es un archivo de texto (.pad); abra el modelo, no una malla, una imagen ni un archivo comprimido</translation>
    </message>
    <message>
        <location line="-3" />
        <source>this is not a text file (%1 control characters in its first %2 bytes)</source>
        <translation>este no es un archivo de texto (%1 caracteres de control en sus primeros %2 bytes)</translation>
    </message>
    <message>
        <location line="+20" />
        <source>the file is not UTF-8 (byte 0x%1 here); it was read as Latin-1 (ISO 8859-1)</source>
        <translation>el archivo no está en UTF-8 (byte 0x%1 aquí); se leyó como Latin-1 (ISO 8859-1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>save the file as UTF-8 so every editor shows its accents the same way</source>
        <translation>guarde el archivo en UTF-8 para que todos los editores muestren sus tildes de la misma forma</translation>
    </message>
    <message>
        <location line="+65" />
        <source>a model file</source>
        <translation>un archivo de modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a model is a short text; put meshes in their own files (G … MESH "file")</source>
        <translation>un modelo es un texto corto; ponga las mallas en sus propios archivos (G … MESH "file")</translation>
    </message>
    <message>
        <location filename="../solver/spec/validate.cpp" line="-587" />
        <source>body %1 (%2)</source>
        <translation>cuerpo %1 (%2)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>joint %1 (%2)</source>
        <translation>articulación %1 (%2)</translation>
    </message>
    <message>
        <location filename="../solver/parse/parser.cpp" line="+761" />
        <location filename="../solver/spec/validate.cpp" line="+5" />
        <source>drive on joint %1</source>
        <translation>accionamiento de la articulación %1</translation>
    </message>
    <message>
        <location filename="../solver/spec/validate.cpp" line="+16" />
        <source>%1 is defined twice (first at line %2)</source>
        <translation>%1 tiene dos definiciones (la primera en la línea %2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give it another id or remove one of the two</source>
        <translation>dele otro id o elimine una de las dos</translation>
    </message>
    <message>
        <location line="+17" />
        <source>body 0 is the ground and cannot have a mass or inertia</source>
        <translation>el cuerpo 0 es la tierra y no puede tener masa ni inercia</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove the numbers from 'B 0', or give the body another id</source>
        <translation>quite los números de 'B 0', o dele otro id al cuerpo</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 has a negative mass (%2 kg)</source>
        <translation>el %1 tiene masa negativa (%2 kg)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a mass is zero or positive, in kg</source>
        <translation>una masa es cero o positiva, en kg</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1's mass %2 kg is beyond any machine's (at most %3 kg)</source>
        <translation>la masa del %1, %2 kg, supera la de cualquier máquina (como máximo %3 kg)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>check the units: a mass is in kg</source>
        <translation>revise las unidades: una masa va en kg</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1's inertia %2 kg m² is beyond any machine's (at most %3 kg m²)</source>
        <translation>la inercia del %1, %2 kg m², supera la de cualquier máquina (como máximo %3 kg m²)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>check the units: moments and products of inertia are in kg m²</source>
        <translation>revise las unidades: los momentos y productos de inercia van en kg m²</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1's inertia tensor is not positive semi-definite (principal moments %2, %3, %4 kg m²)</source>
        <translation>el tensor de inercia del %1 no es semidefinido positivo (momentos principales %2, %3, %4 kg m²)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>moments of inertia are zero or positive, and products of inertia cannot outweigh them; check signs and units (kg m²)</source>
        <translation>los momentos de inercia son cero o positivos, y los productos de inercia no pueden superarlos; revise signos y unidades (kg m²)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1's principal moments of inertia %2, %3, %4 kg m² break the triangle inequality (%2 + %3 &lt; %4): no real body has them</source>
        <translation>los momentos principales de inercia del %1 (%2, %3, %4 kg m²) no cumplen la desigualdad triangular (%2 + %3 &lt; %4): ningún cuerpo real los tiene</translation>
    </message>
    <message>
        <location line="+6" />
        <source>check the values; the inertia calculator computes them from the body's shapes</source>
        <translation>revise los valores; la calculadora de inercia los obtiene de las formas del cuerpo</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 has no mass but a non-zero inertia</source>
        <translation>el %1 no tiene masa, pero sí una inercia distinta de cero</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give its mass, or set the inertia to zero as well</source>
        <translation>indique su masa, o deje también la inercia en cero</translation>
    </message>
    <message>
        <location line="+12" />
        <location line="+5" />
        <location line="+337" />
        <location line="+84" />
        <source>%1: %2 has zero length</source>
        <translation>%1: %2 tiene longitud cero</translation>
    </message>
    <message>
        <location line="-425" />
        <source>the axis is a direction, e.g. A%1 0 0 1</source>
        <translation>el eje es una dirección, p. ej. A%1 0 0 1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the reference direction is a direction perpendicular to A%1, e.g. R%1 0 1 0</source>
        <translation>la dirección de referencia es una dirección perpendicular a A%1, p. ej. R%1 0 1 0</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: R%2 is parallel to A%2</source>
        <translation>%1: R%2 es paralelo a A%2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>R%1 must be perpendicular to the axis A%1</source>
        <translation>R%1 debe ser perpendicular al eje A%1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: R%2 is not perpendicular to A%2 (angle %3°); R%2 is made perpendicular</source>
        <translation>%1: R%2 no es perpendicular a A%2 (ángulo %3°); R%2 se corrige para que lo sea</translation>
    </message>
    <message>
        <location line="+4" />
        <source>write R%1 at 90° to A%1</source>
        <translation>escriba R%1 a 90° de A%1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>joint %1 is a free joint (T 3): %2 does not apply to it</source>
        <translation>la articulación %1 es una articulación libre (T 3): %2 no se aplica a ella</translation>
    </message>
    <message>
        <location line="+3" />
        <source>remove %1; place the free body with the joint's P1, A1 and R1 (it starts where its two joint frames coincide, at rest)</source>
        <translation>quite %1; ubique el cuerpo libre con P1, A1 y R1 de la articulación (parte donde coinciden sus dos sistemas de la articulación, en reposo)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>joint %1 is a free joint (T 3) whose B2 is the ground</source>
        <translation>la articulación %1 es una articulación libre (T 3) cuyo B2 es tierra</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the free body is B2: write B1 0 … and B2 with the body that moves</source>
        <translation>el cuerpo libre es B2: escriba B1 0 … y B2 con el cuerpo que se mueve</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1 has no B%2 line</source>
        <translation>la %1 no tiene línea B%2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>follow the C line with B%1 body P%1 x y z A%1 x y z R%1 x y z</source>
        <translation>ponga después de la línea C: B%1 body P%1 x y z A%1 x y z R%1 x y z</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: body %2 (B%3) is not defined</source>
        <translation>%1: el cuerpo %2 (B%3) no está definido</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add 'B %1 m Ixx Iyy Izz', or use an existing body</source>
        <translation>agregue 'B %1 m Ixx Iyy Izz', o use un cuerpo existente</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 connects body %2 to itself</source>
        <translation>la %1 conecta el cuerpo %2 consigo mismo</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+262" />
        <source>B1 and B2 must name two different bodies</source>
        <translation>B1 y B2 deben indicar dos cuerpos distintos</translation>
    </message>
    <message>
        <location line="-255" />
        <source>%1 is a pivoted linear actuator (T 1) but has no CL1/CL2 line</source>
        <translation>la %1 es un actuador lineal pivotado (T 1), pero no tiene línea CL1/CL2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is a pivoted linear actuator (T 1) but has no %2</source>
        <translation>la %1 es un actuador lineal pivotado (T 1), pero no tiene %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>add 'CL1 x y z CL2 x y z': the actuator's ends on body B1 and body B2, in their local frames</source>
        <translation>agregue 'CL1 x y z CL2 x y z': los extremos del actuador en el cuerpo B1 y en el cuerpo B2, en sus sistemas de referencia locales</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 has CL1/CL2 but is not a pivoted linear actuator</source>
        <translation>la %1 tiene CL1/CL2, pero no es un actuador lineal pivotado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>CL1/CL2 belong to T 1 joints; add 'T 1' to the C line, or remove the CL line</source>
        <translation>CL1/CL2 son propios de las articulaciones T 1; agregue 'T 1' a la línea C, o quite la línea CL</translation>
    </message>
    <message>
        <location line="+14" />
        <source>%1: %2 = %3 is beyond any machine's (at most %4 in size)</source>
        <translation>%1: %2 = %3 excede lo de cualquier máquina (a lo más %4 en magnitud)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>check the units: lengths in m, angles in rad, rates in m/s or rad/s</source>
        <translation>revise las unidades: longitudes en m, ángulos en rad, velocidades en m/s o rad/s</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the lower limit LL = %2 is above the upper limit UL = %3</source>
        <translation>%1: el límite inferior LL = %2 está por encima del límite superior UL = %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>swap LL and UL</source>
        <translation>intercambie LL y UL</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+9" />
        <source>%1: %2 = %3 m, but a T 1 joint's coordinate is the actuator's length</source>
        <translation>%1: %2 = %3 m, pero la coordenada de una articulación T 1 es la longitud del actuador</translation>
    </message>
    <message>
        <location line="-5" />
        <source>give the cylinder's length between CL1 and CL2, in metres (positive)</source>
        <translation>indique la longitud del cilindro entre CL1 y CL2, en metros (positiva)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>give the cylinder's initial length between CL1 and CL2, in metres (positive)</source>
        <translation>indique la longitud inicial del cilindro entre CL1 y CL2, en metros (positiva)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: QI = %2 is below the lower limit LL = %3</source>
        <translation>%1: QI = %2 está por debajo del límite inferior LL = %3</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+7" />
        <source>give QI between LL and UL</source>
        <translation>indique un QI entre LL y UL</translation>
    </message>
    <message>
        <location line="-4" />
        <source>%1: QI = %2 is above the upper limit UL = %3</source>
        <translation>%1: QI = %2 está por encima del límite superior UL = %3</translation>
    </message>
    <message>
        <location line="+12" />
        <source>%1: VI = %2 moves the joint past its upper limit UL = %3, where it starts</source>
        <translation>%1: VI = %2 lleva la articulación más allá de su límite superior UL = %3, donde parte</translation>
    </message>
    <message>
        <location line="+4" />
        <source>start it inside its limits, or give VI ≤ 0</source>
        <translation>hágala partir dentro de sus límites, o indique VI ≤ 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: VI = %2 moves the joint past its lower limit LL = %3, where it starts</source>
        <translation>%1: VI = %2 lleva la articulación más allá de su límite inferior LL = %3, donde parte</translation>
    </message>
    <message>
        <location line="+4" />
        <source>start it inside its limits, or give VI ≥ 0</source>
        <translation>hágala partir dentro de sus límites, o indique VI ≥ 0</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: a CYL drive needs a T 1 or T 2 joint, but %2 is revolute</source>
        <translation>%1: un accionamiento CYL necesita una articulación T 1 o T 2, pero la %2 es de revolución</translation>
    </message>
    <message>
        <location line="+3" />
        <source>drive a revolute joint with D j HMOTOR PUMP id DISP Dm VALVE Qn DP dp, or make the joint T 1 (a pivoted cylinder) or T 2</source>
        <translation>accione una articulación de revolución con D j HMOTOR PUMP id DISP Dm VALVE Qn DP dp, o haga la articulación T 1 (un cilindro pivotado) o T 2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: an HMOTOR drive turns a revolute joint, but %2 is T %3</source>
        <translation>%1: un accionamiento HMOTOR hace girar una articulación de revolución, pero la %2 es T %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>drive a T 1 or T 2 joint with D j CYL PUMP id BORE d ROD d VALVE Qn DP dp</source>
        <translation>accione una articulación T 1 o T 2 con D j CYL PUMP id BORE d ROD d VALVE Qn DP dp</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: a CYL drive needs the stroke, but %2 has no %3</source>
        <translation>%1: un accionamiento CYL necesita la carrera, pero la %2 no tiene %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>give the joint LL (fully retracted) and UL (fully extended): the chamber volumes follow from them</source>
        <translation>indique LL (totalmente retraído) y UL (totalmente extendido) de la articulación: de ellos resultan los volúmenes de las cámaras</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: the stroke of %2 is empty (LL %3 ≥ UL %4)</source>
        <translation>%1: la carrera de la %2 es nula (LL %3 ≥ UL %4)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>LL is the fully retracted and UL the fully extended coordinate</source>
        <translation>LL es la coordenada totalmente retraída y UL la totalmente extendida</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: pump %2 is not defined</source>
        <translation>%1: la bomba %2 no está definida</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add a PUMP id FLOW Qmax PRESSURE p_max statement</source>
        <translation>agregue una instrucción PUMP id FLOW Qmax PRESSURE p_max</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the pumps are %1</source>
        <translation>las bombas son %1</translation>
    </message>
    <message>
        <location line="+11" />
        <location line="+71" />
        <source>%1: joint %2 is not defined</source>
        <translation>%1: la articulación %2 no está definida</translation>
    </message>
    <message>
        <location line="-70" />
        <location line="+71" />
        <source>use the id of a joint (C id …)</source>
        <translation>use el id de una articulación (C id …)</translation>
    </message>
    <message>
        <location line="-65" />
        <source>%1 already has a drive (line %2)</source>
        <translation>la %1 ya tiene un accionamiento (línea %2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>one joint takes one drive; remove one of them</source>
        <translation>cada articulación lleva un solo accionamiento; quite uno de ellos</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: %2 is a free joint (T 3), which no drive can move</source>
        <translation>%1: la %2 es una articulación libre (T 3), que ningún accionamiento puede mover</translation>
    </message>
    <message>
        <location line="+3" />
        <source>drive a T 0, T 1 or T 2 joint; push a free body with a force (F … POINT) instead</source>
        <translation>accione una articulación T 0, T 1 o T 2; para empujar un cuerpo libre use una fuerza (F … POINT)</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1: PUMP/BORE/ROD describe a cylinder, but %2 is revolute</source>
        <translation>%1: PUMP/BORE/ROD describen un cilindro, pero la %2 es de revolución</translation>
    </message>
    <message>
        <location line="+3" />
        <source>for a hydraulic motor give VMAX (rad/s) and FMAX (N·m); or make the joint T 1 or T 2</source>
        <translation>para un motor hidráulico indique VMAX (rad/s) y FMAX (N·m); o haga la articulación T 1 o T 2</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1: VI = %2 is faster than its hydraulic drive can move it (%3, from its pump and cylinder data)</source>
        <translation>%1: VI = %2 supera la velocidad a la que su accionamiento hidráulico puede moverla (%3, según los datos de su bomba y su cilindro)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: VI = %2 is faster than its hydraulic drive can move it (%3)</source>
        <translation>%1: VI = %2 supera la velocidad a la que su accionamiento hidráulico puede moverla (%3)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>give |VI| ≤ flow / bore area (extending) or flow / annulus area (retracting)</source>
        <translation>indique |VI| ≤ caudal / área del pistón (al extender) o caudal / área anular (al retraer)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>give |VI| ≤ VMAX (extending) or VMIN (retracting)</source>
        <translation>indique |VI| ≤ VMAX (al extender) o VMIN (al retraer)</translation>
    </message>
    <message>
        <location filename="../solver/parse/parser.cpp" line="+274" />
        <location filename="../solver/spec/validate.cpp" line="+10" />
        <location line="+178" />
        <source>force %1</source>
        <translation>fuerza %1</translation>
    </message>
    <message>
        <location filename="../solver/spec/validate.cpp" line="-174" />
        <location line="+71" />
        <source>%1: body %2 is not defined</source>
        <translation>%1: el cuerpo %2 no está definido</translation>
    </message>
    <message>
        <location line="-70" />
        <source>use the id of a body (B id …)</source>
        <translation>use el id de un cuerpo (B id …)</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1: joint %2 is a free joint (T 3), which has no single coordinate</source>
        <translation>%1: la articulación %2 es una articulación libre (T 3), que no tiene una coordenada única</translation>
    </message>
    <message>
        <location line="+3" />
        <source>use a T 0, T 1 or T 2 joint here; load a free body with a force on the body (F … POINT or TORQUE)</source>
        <translation>use aquí una articulación T 0, T 1 o T 2; cargue un cuerpo libre con una fuerza sobre el cuerpo (F … POINT o TORQUE)</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+125" />
        <source>%1: %2 is negative</source>
        <translation>%1: %2 es negativo</translation>
    </message>
    <message>
        <location line="-120" />
        <location line="+90" />
        <location line="+34" />
        <source>%1: %2 must be positive</source>
        <translation>%1: %2 debe ser positivo</translation>
    </message>
    <message>
        <location line="-113" />
        <source>%1: the spring connects body %2 to itself</source>
        <translation>%1: el resorte conecta el cuerpo %2 consigo mismo</translation>
    </message>
    <message>
        <location line="+13" />
        <source>give the force's direction, e.g. DIR 0 0 -1</source>
        <translation>indique la dirección de la fuerza, p. ej. DIR 0 0 -1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a stiffness is ≥ 0, in N/m</source>
        <translation>una rigidez es ≥ 0, en N/m</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a rest length is ≥ 0, in m</source>
        <translation>una longitud en reposo es ≥ 0, en m</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a damping is ≥ 0, in N s/m</source>
        <translation>un amortiguamiento es ≥ 0, en N s/m</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the reference area in m²</source>
        <translation>el área de referencia en m²</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a drag coefficient is ≥ 0</source>
        <translation>un coeficiente de arrastre es ≥ 0</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the fluid's density in kg/m³ (air: 1.225)</source>
        <translation>la densidad del fluido en kg/m³ (aire: 1.225)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>use the id of a body (B id …), or 0 for the ground</source>
        <translation>use el id de un cuerpo (B id …), o 0 para la tierra</translation>
    </message>
    <message>
        <location line="+14" />
        <source>%1: the PRISM's height H must be positive</source>
        <translation>%1: la altura H del PRISM debe ser positiva</translation>
    </message>
    <message>
        <location line="+1" />
        <source>H is in metres</source>
        <translation>H va en metros</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: the PRISM's outline has no area</source>
        <translation>%1: el contorno del PRISM no tiene área</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give at least three x y vertices that are not on one line</source>
        <translation>indique al menos tres vértices x y que no estén en una misma línea</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: %2 dimension %3 must be positive, not %4</source>
        <translation>%1: la dimensión %3 de %2 debe ser positiva, no %4</translation>
    </message>
    <message>
        <location line="+5" />
        <source>dimensions are lengths in metres</source>
        <translation>las dimensiones son longitudes en metros</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: the TUBE's inner radius is not smaller than its outer radius</source>
        <translation>%1: el radio interior del TUBE no es menor que su radio exterior</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write TUBE RO RI L with RI &lt; RO</source>
        <translation>escriba TUBE RO RI L con RI &lt; RO</translation>
    </message>
    <message>
        <location line="+5" />
        <source>SCALE 0.001 turns millimetres into metres</source>
        <translation>SCALE 0.001 convierte milímetros en metros</translation>
    </message>
    <message>
        <location line="+17" />
        <source>give a direction, e.g. AXIS 1 0 0</source>
        <translation>indique una dirección, p. ej. AXIS 1 0 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: the ROT axis has zero length</source>
        <translation>%1: el eje de ROT tiene longitud cero</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write ROT ax ay az degrees, e.g. ROT 0 0 1 90</source>
        <translation>escriba ROT ax ay az grados, p. ej. ROT 0 0 1 90</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: COLOR components must lie between 0 and 1</source>
        <translation>%1: las componentes de COLOR deben estar entre 0 y 1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write COLOR r g b with 0 ≤ r, g, b ≤ 1 (e.g. 0.8 0.1 0.1 for red)</source>
        <translation>escriba COLOR r g b con 0 ≤ r, g, b ≤ 1 (p. ej. 0.8 0.1 0.1 para rojo)</translation>
    </message>
    <message>
        <location line="+19" />
        <source>the model has %1 bodies; Padrob takes at most %2</source>
        <translation>el modelo tiene %1 cuerpos; Padrob admite como máximo %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>split the machine into smaller models, or merge bodies that move together</source>
        <translation>divida la máquina en modelos más pequeños, o una los cuerpos que se mueven juntos</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the model has %1 joints; Padrob takes at most %2</source>
        <translation>el modelo tiene %1 articulaciones; Padrob admite como máximo %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>split the machine into smaller models, or remove joints that never move</source>
        <translation>divida la máquina en modelos más pequeños, o elimine las articulaciones que nunca se mueven</translation>
    </message>
    <message>
        <location filename="../solver/parse/lexer.cpp" line="+139" />
        <source>unexpected control character (code %1)</source>
        <translation>carácter de control inesperado (código %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>delete it; a model file is plain text</source>
        <translation>bórrelo; un archivo de modelo es texto plano</translation>
    </message>
    <message>
        <location line="+35" />
        <source>the string has no closing quote</source>
        <translation>el texto entre comillas no tiene comilla de cierre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add '"' at the end of the text</source>
        <translation>agregue '"' al final del texto</translation>
    </message>
    <message>
        <location filename="../solver/parse/parser.cpp" line="-1230" />
        <source>write %1</source>
        <translation>escriba %1</translation>
    </message>
    <message>
        <location line="+29" />
        <source>did you mean '%1'?</source>
        <translation>¿quiso decir '%1'?</translation>
    </message>
    <message>
        <location line="+59" />
        <source>a statement cannot start with a string</source>
        <translation>una instrucción no puede empezar con un texto entre comillas</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a statement starts with a keyword, not with the number %1</source>
        <translation>una instrucción empieza con una palabra clave, no con el número %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>start the line with GRAVITY, B, C, D, F or G, or join it to the line above</source>
        <translation>empiece la línea con GRAVITY, B, C, D, F o G, o únala a la línea anterior</translation>
    </message>
    <message>
        <location line="+21" />
        <source>unknown keyword '%1'</source>
        <translation>palabra clave desconocida '%1'</translation>
    </message>
    <message>
        <location line="+86" />
        <source>%1: %2 is out of range</source>
        <translation>%1: %2 está fuera de rango</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a number must lie within ±1.7e308</source>
        <translation>un número debe estar dentro de ±1.7e308</translation>
    </message>
    <message>
        <location line="+3" />
        <source>numbers look like 12, -0.5, .2 or 1e-3</source>
        <translation>los números se escriben como 12, -0.5, .2 o 1e-3</translation>
    </message>
    <message>
        <location line="+15" />
        <location line="+42" />
        <location line="+271" />
        <source>%1: %2 is missing</source>
        <translation>%1: falta %2</translation>
    </message>
    <message>
        <location line="-309" />
        <source>%1: expected %2, found '%3'</source>
        <translation>%1: se esperaba %2, pero se encontró '%3'</translation>
    </message>
    <message>
        <location line="+20" />
        <source>%1: %2 needs %3 numbers, only %4 given</source>
        <translation>%1: %2 necesita %3 números, solo se dieron %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: %2 needs %3 numbers, the line ends</source>
        <translation>%1: %2 necesita %3 números, pero la línea termina</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: %2 needs %3 numbers, found '%4'</source>
        <translation>%1: %2 necesita %3 números, pero se encontró '%4'</translation>
    </message>
    <message>
        <location line="+17" />
        <source>%1: %2 is missing, found '%3'</source>
        <translation>%1: falta %2, se encontró '%3'</translation>
    </message>
    <message>
        <location line="+16" />
        <location line="+810" />
        <location line="+112" />
        <source>%1: %2 cannot be negative (%3)</source>
        <translation>%1: %2 no puede ser negativo (%3)</translation>
    </message>
    <message>
        <location line="-921" />
        <location line="+4" />
        <source>ids are whole numbers 0, 1, 2, …</source>
        <translation>los id son números enteros 0, 1, 2, …</translation>
    </message>
    <message>
        <location line="-1" />
        <source>%1: %2 must be a whole number, not %3</source>
        <translation>%1: %2 debe ser un número entero, no %3</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: %2 %3 is too large</source>
        <translation>%1: %2 %3 es demasiado grande</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ids go from 0 to %1</source>
        <translation>los id van de 0 a %1</translation>
    </message>
    <message>
        <location line="+9" />
        <source>write MAG value, MAG SIN amp freq phase [offset], MAG TABLE T t1 v1 t2 v2 … or MAG TABLE Q joint q1 v1 …</source>
        <translation>escriba MAG value, MAG SIN amp freq phase [offset], MAG TABLE T t1 v1 t2 v2 … o MAG TABLE Q joint q1 v1 …</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the magnitude</source>
        <translation>la magnitud</translation>
    </message>
    <message>
        <location line="+16" />
        <source>the offset</source>
        <translation>el desplazamiento (offset)</translation>
    </message>
    <message>
        <location line="+16" />
        <source>the joint of TABLE Q</source>
        <translation>la articulación de TABLE Q</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: TABLE must say T (by time) or Q (by a joint's coordinate)</source>
        <translation>%1: TABLE debe indicar T (según el tiempo) o Q (según la coordenada de una articulación)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>write TABLE T t1 v1 t2 v2 … or TABLE Q joint q1 v1 q2 v2 …</source>
        <translation>escriba TABLE T t1 v1 t2 v2 … o TABLE Q joint q1 v1 q2 v2 …</translation>
    </message>
    <message>
        <location line="+10" />
        <source>a table value</source>
        <translation>un valor de la tabla</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: a TABLE needs pairs of numbers (abscissa value), found %2 number</source>
        <translation>%1: una TABLE necesita pares de números (abscisa valor); se encontró %2 número</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: a TABLE needs pairs of numbers (abscissa value), found %2 numbers</source>
        <translation>%1: una TABLE necesita pares de números (abscisa valor); se encontraron %2 números</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: table abscissae must increase (%2 follows %3)</source>
        <translation>%1: las abscisas de la tabla deben ser crecientes (%2 viene después de %3)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>sort the pairs by their first number and remove repeats</source>
        <translation>ordene los pares por su primer número y quite los repetidos</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1: MAG needs a value</source>
        <translation>%1: MAG necesita un valor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: MAG needs a value, found '%2'</source>
        <translation>%1: MAG necesita un valor, pero se encontró '%2'</translation>
    </message>
    <message>
        <location line="+28" />
        <source>%1: unexpected number %2</source>
        <translation>%1: número inesperado %2</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+11" />
        <source>remove it</source>
        <translation>quítelo</translation>
    </message>
    <message>
        <location line="-10" />
        <source>remove it, or put an option before it (%1)</source>
        <translation>quítelo, o ponga una opción antes de él (%1)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: '%2' is not an option of %3</source>
        <translation>%1: '%2' no es una opción de %3</translation>
    </message>
    <message>
        <location line="+6" />
        <source>options are %1</source>
        <translation>las opciones son %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>write %1 %2</source>
        <translation>escriba %1 %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 after %2</source>
        <translation>%1 después de %2</translation>
    </message>
    <message>
        <location line="+30" />
        <source>%1: %2 needs a word</source>
        <translation>%1: %2 necesita una palabra</translation>
    </message>
    <message>
        <location line="+17" />
        <location line="+5" />
        <source>%1: %2 needs a text in double quotes</source>
        <translation>%1: %2 necesita un texto entre comillas dobles</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+431" />
        <source>%1: %2 is given twice</source>
        <translation>%1: %2 aparece dos veces</translation>
    </message>
    <message>
        <location line="-430" />
        <location line="+431" />
        <source>keep one %1</source>
        <translation>deje un solo %1</translation>
    </message>
    <message>
        <location line="-389" />
        <source>write GRAVITY gx gy gz (m/s², z is up)</source>
        <translation>escriba GRAVITY gx gy gz (m/s², z hacia arriba)</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+22" />
        <location line="+21" />
        <source>%1 is given twice (first at line %2)</source>
        <translation>%1 aparece dos veces (la primera en la línea %2)</translation>
    </message>
    <message>
        <location line="-40" />
        <location line="+22" />
        <location line="+19" />
        <source>keep one %1 statement</source>
        <translation>deje una sola instrucción %1</translation>
    </message>
    <message>
        <location line="-27" />
        <location line="+77" />
        <source>the coefficient of restitution</source>
        <translation>el coeficiente de restitución</translation>
    </message>
    <message>
        <location line="-76" />
        <source>write RESTITUTION e (0 inelastic … 1 elastic)</source>
        <translation>escriba RESTITUTION e (0 inelástico … 1 elástico)</translation>
    </message>
    <message>
        <location line="+14" />
        <source>RESTITUTION %1 is outside 0 … 1</source>
        <translation>RESTITUTION %1 está fuera de 0 … 1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>0 stops a joint dead at its limit, 1 bounces it back at the same speed</source>
        <translation>0 detiene en seco la articulación en su límite; 1 la hace rebotar a la misma velocidad</translation>
    </message>
    <message>
        <location line="+32" />
        <source>the bulk modulus in Pa</source>
        <translation>el módulo de compresibilidad en Pa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the laminar pressure difference in Pa</source>
        <translation>la diferencia de presión laminar en Pa</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the effective bulk modulus of oil in hoses is about 1e9 Pa</source>
        <translation>el módulo de compresibilidad efectivo del aceite en mangueras es de unos 1e9 Pa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a few bar, e.g. LAMINAR 2e5</source>
        <translation>unos pocos bar, p. ej. LAMINAR 2e5</translation>
    </message>
    <message>
        <location line="+15" />
        <source>the friction coefficient</source>
        <translation>el coeficiente de roce</translation>
    </message>
    <message>
        <location line="+7" />
        <source>CONTACT MU %1 is negative</source>
        <translation>CONTACT MU %1 es negativo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MU is the Coulomb friction coefficient, 0 (frictionless) or more: steel on steel about 0.2 … 0.6</source>
        <translation>MU es el coeficiente de roce de Coulomb, 0 (sin roce) o más: acero sobre acero, cerca de 0.2 … 0.6</translation>
    </message>
    <message>
        <location line="+10" />
        <source>CONTACT E %1 is outside 0 … 1</source>
        <translation>CONTACT E %1 está fuera de 0 … 1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>0 stops a solid dead where it hits, 1 bounces it back at the same speed</source>
        <translation>0 detiene en seco un sólido donde choca; 1 lo hace rebotar a la misma velocidad</translation>
    </message>
    <message>
        <location line="+15" />
        <source>pump</source>
        <translation>bomba</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+425" />
        <location line="+14" />
        <source>the pump id</source>
        <translation>el id de la bomba</translation>
    </message>
    <message>
        <location line="-435" />
        <source>pump %1</source>
        <translation>bomba %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the largest flow in m³/s</source>
        <translation>el caudal máximo en m³/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the pressure setting in Pa</source>
        <translation>la presión de ajuste en Pa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the load-sensing margin in Pa</source>
        <translation>el margen de detección de carga en Pa</translation>
    </message>
    <message>
        <location line="+10" />
        <source>FLOW in m³/s (45 cm³/rev at 1480 rpm is 1.11e-3), PRESSURE and MARGIN in Pa</source>
        <translation>FLOW en m³/s (45 cm³/rev a 1480 rpm son 1.11e-3), PRESSURE y MARGIN en Pa</translation>
    </message>
    <message>
        <location line="+8" />
        <source>pump %1 is defined twice (first at line %2)</source>
        <translation>la bomba %1 tiene dos definiciones (la primera en la línea %2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give each pump its own id</source>
        <translation>dé a cada bomba su propio id</translation>
    </message>
    <message>
        <location line="+13" />
        <location line="+519" />
        <source>body</source>
        <translation>cuerpo</translation>
    </message>
    <message>
        <location line="-519" />
        <location line="+188" />
        <location line="+455" />
        <source>the body id</source>
        <translation>el id del cuerpo</translation>
    </message>
    <message>
        <location line="-619" />
        <source>%1: a body takes 0, 4 or 7 numbers after its id (m Ixx Iyy Izz [Ixy Iyz Ixz]), found %2</source>
        <translation>%1: un cuerpo lleva 0, 4 o 7 números después de su id (m Ixx Iyy Izz [Ixy Iyz Ixz]); se encontraron %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>give the mass and the three moments of inertia: %1</source>
        <translation>indique la masa y los tres momentos de inercia: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give all three products of inertia Ixy Iyz Ixz, or none</source>
        <translation>indique los tres productos de inercia Ixy Iyz Ixz, o ninguno</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove the extra numbers</source>
        <translation>quite los números sobrantes</translation>
    </message>
    <message>
        <location line="+20" />
        <source>a body statement (B)</source>
        <translation>una instrucción de cuerpo (B)</translation>
    </message>
    <message>
        <location line="+17" />
        <location line="+5" />
        <source>joint</source>
        <translation>articulación</translation>
    </message>
    <message>
        <location line="-5" />
        <location line="+165" />
        <location line="+327" />
        <source>the joint id</source>
        <translation>el id de la articulación</translation>
    </message>
    <message>
        <location line="-484" />
        <source>the lower limit</source>
        <translation>el límite inferior</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the upper limit</source>
        <translation>el límite superior</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the initial coordinate</source>
        <translation>la coordenada inicial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the initial rate</source>
        <translation>la velocidad inicial</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a joint statement (C)</source>
        <translation>una instrucción de articulación (C)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: there is no joint type T %2</source>
        <translation>%1: no existe el tipo de articulación T %2</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: DEG after %2, but the coordinate of %3 is a length</source>
        <translation>%1: DEG después de %2, pero la coordenada de %3 es una longitud</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a pivoted linear actuator (T 1)</source>
        <translation>un actuador lineal pivotado (T 1)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a prismatic joint (T 2)</source>
        <translation>una articulación prismática (T 2)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove DEG; give the value in metres</source>
        <translation>quite DEG; indique el valor en metros</translation>
    </message>
    <message>
        <location line="+21" />
        <source>%1 must follow a joint statement (C)</source>
        <translation>%1 debe ir después de una instrucción de articulación (C)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put it right after its joint's C line (blank and comment lines may come between)</source>
        <translation>póngala justo después de la línea C de su articulación (puede haber líneas en blanco y comentarios entre medio)</translation>
    </message>
    <message>
        <location line="+15" />
        <source>joint %1, B%2</source>
        <translation>articulación %1, B%2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>joint %1 already has a B%2 line (line %3)</source>
        <translation>la articulación %1 ya tiene una línea B%2 (línea %3)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>keep one B%1 line per joint</source>
        <translation>deje una sola línea B%1 por articulación</translation>
    </message>
    <message>
        <location line="+24" />
        <source>%1: %2 belongs on the B%3 line</source>
        <translation>%1: %2 va en la línea B%3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>on the B%1 line write %2</source>
        <translation>en la línea B%1 escriba %2</translation>
    </message>
    <message>
        <location line="+8" />
        <source>a B%1 line</source>
        <translation>una línea B%1</translation>
    </message>
    <message>
        <location line="+20" />
        <source>a CL1/CL2 line</source>
        <translation>una línea CL1/CL2</translation>
    </message>
    <message>
        <location line="+22" />
        <source>drive</source>
        <translation>accionamiento</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the drive kind is missing</source>
        <translation>%1: falta el tipo de accionamiento</translation>
    </message>
    <message>
        <location line="+7" />
        <source>speed</source>
        <translation>velocidad</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+261" />
        <source>force</source>
        <translation>fuerza</translation>
    </message>
    <message>
        <location line="-260" />
        <location line="+138" />
        <location line="+1" />
        <source>diameter</source>
        <translation>diámetro</translation>
    </message>
    <message>
        <location line="-139" />
        <source>gain</source>
        <translation>ganancia</translation>
    </message>
    <message>
        <location line="+40" />
        <source>write D j HYD VMAX v [VMIN v] [FMAX f] [FMIN f], or D j HYD PUMP cc RPM n BORE d ROD d PRESSURE Pa</source>
        <translation>escriba D j HYD VMAX v [VMIN v] [FMAX f] [FMIN f], o D j HYD PUMP cc RPM n BORE d ROD d PRESSURE Pa</translation>
    </message>
    <message>
        <location line="-35" />
        <source>stall torque</source>
        <translation>torque de bloqueo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no-load speed</source>
        <translation>velocidad en vacío</translation>
    </message>
    <message>
        <location line="+25" />
        <source>%1: unknown drive kind '%2'</source>
        <translation>%1: tipo de accionamiento desconocido '%2'</translation>
    </message>
    <message>
        <location line="+19" />
        <location line="+119" />
        <source>a %1 drive</source>
        <translation>un accionamiento %1</translation>
    </message>
    <message>
        <location line="-99" />
        <source>%1: give either VMAX/FMAX or the hydraulic data PUMP … PRESSURE, not both</source>
        <translation>%1: indique VMAX/FMAX o los datos hidráulicos PUMP … PRESSURE, no ambos</translation>
    </message>
    <message>
        <location line="+2" />
        <source>remove one of the two forms</source>
        <translation>quite una de las dos formas</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: %2 follows from the hydraulic data PUMP … PRESSURE</source>
        <translation>%1: %2 se deduce de los datos hidráulicos PUMP … PRESSURE</translation>
    </message>
    <message>
        <location line="+3" />
        <source>remove %1, or give VMAX/VMIN/FMAX/FMIN instead of the pump data</source>
        <translation>quite %1, o indique VMAX/VMIN/FMAX/FMIN en lugar de los datos de la bomba</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+154" />
        <source>%1: the rod (%2 m) is not thinner than the bore (%3 m)</source>
        <translation>%1: el vástago (%2 m) no es más delgado que el diámetro interior del cilindro (%3 m)</translation>
    </message>
    <message>
        <location line="-150" />
        <location line="+154" />
        <source>ROD and BORE are diameters in metres; the rod must be thinner</source>
        <translation>ROD y BORE son diámetros en metros; el vástago debe ser más delgado</translation>
    </message>
    <message>
        <location line="-149" />
        <source>%1: a hydraulic drive needs VMAX or the pump data</source>
        <translation>%1: un accionamiento hidráulico necesita VMAX o los datos de la bomba</translation>
    </message>
    <message>
        <location line="-438" />
        <location line="+68" />
        <location line="+385" />
        <location line="+106" />
        <location line="+12" />
        <source>%1: %2 must be positive, not %3</source>
        <translation>%1: %2 debe ser positivo, no %3</translation>
    </message>
    <message>
        <location line="-1086" />
        <source>statements are GRAVITY, RESTITUTION, FLUID, PUMP, B, C (with B1, B2, CL1), D, F and G; comments start with // or #</source>
        <translation>las instrucciones son GRAVITY, RESTITUTION, FLUID, PUMP, B, C (con B1, B2, CL1), D, F y G; los comentarios empiezan con // o #</translation>
    </message>
    <message>
        <location line="+682" />
        <source>the joint type (0, 1, 2 or 3)</source>
        <translation>el tipo de articulación (0, 1, 2 o 3)</translation>
    </message>
    <message>
        <location line="+20" />
        <source>use T 0 (revolute, the default), T 1 (pivoted linear actuator), T 2 (prismatic) or T 3 (free body)</source>
        <translation>use T 0 (de revolución, por omisión), T 1 (actuador lineal pivotado), T 2 (prismática) o T 3 (cuerpo libre)</translation>
    </message>
    <message>
        <location line="+145" />
        <source>write HYD, MOTOR, PNEU, SERVO, CYL or HMOTOR after the joint id</source>
        <translation>escriba HYD, MOTOR, PNEU, SERVO, CYL o HMOTOR después del id de la articulación</translation>
    </message>
    <message>
        <location line="+39" />
        <source>drive kinds are HYD, MOTOR, PNEU, SERVO, CYL and HMOTOR</source>
        <translation>los tipos de accionamiento son HYD, MOTOR, PNEU, SERVO, CYL y HMOTOR</translation>
    </message>
    <message>
        <location line="+83" />
        <source>give its magnitude; the direction comes from the operator's command</source>
        <translation>indique su magnitud; el sentido lo da el comando del operador</translation>
    </message>
    <message>
        <location line="+5" />
        <source>gains are zero or positive</source>
        <translation>las ganancias son cero o positivas</translation>
    </message>
    <message>
        <location line="+14" />
        <source>two volumes in m³</source>
        <translation>dos volúmenes en m³</translation>
    </message>
    <message>
        <location line="+1" />
        <source>two pressures in Pa</source>
        <translation>dos presiones en Pa</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+13" />
        <source>the nominal flow in m³/s</source>
        <translation>el caudal nominal en m³/s</translation>
    </message>
    <message>
        <location line="-12" />
        <location line="+13" />
        <source>the nominal pressure drop in Pa</source>
        <translation>la caída de presión nominal en Pa</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+13" />
        <source>the spool time constant in s</source>
        <translation>la constante de tiempo de la corredera en s</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+13" />
        <source>the viscous friction</source>
        <translation>el roce viscoso</translation>
    </message>
    <message>
        <location line="-6" />
        <source>the displacement in m³/rad</source>
        <translation>la cilindrada en m³/rad</translation>
    </message>
    <message>
        <location line="+26" />
        <source>%1: %2 belongs to the prescribed-rate HYD drive, not to %3</source>
        <translation>%1: %2 es del accionamiento HYD de velocidad prescrita, no de %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a CYL drive's speed follows from VALVE and BORE, its force from the PUMP's PRESSURE; remove %1 or write the drive as HYD</source>
        <translation>la velocidad de un accionamiento CYL resulta de VALVE y BORE, y su fuerza de la PRESSURE de la PUMP; quite %1 o escriba el accionamiento como HYD</translation>
    </message>
    <message>
        <location line="+3" />
        <source>an HMOTOR drive's speed follows from VALVE and DISP, its torque from the PUMP's PRESSURE; remove %1 or write the drive as HYD</source>
        <translation>la velocidad de un accionamiento HMOTOR resulta de VALVE y DISP, y su torque de la PRESSURE de la PUMP; quite %1 o escriba el accionamiento como HYD</translation>
    </message>
    <message>
        <location line="+20" />
        <source>%1: COMP %2 is not a compensation</source>
        <translation>%1: COMP %2 no es una compensación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write COMP NONE (orifice law), PRE (pre-compensated) or POST (post-compensated, flow sharing)</source>
        <translation>escriba COMP NONE (ley del orificio), PRE (precompensado) o POST (poscompensado, reparto de caudal)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: P0 %2 is below tank pressure (0)</source>
        <translation>%1: P0 %2 está por debajo de la presión del estanque (0)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>pressures are gauge pressures in Pa, 0 or more</source>
        <translation>las presiones son manométricas, en Pa, 0 o más</translation>
    </message>
    <message>
        <location line="+1" />
        <source>volumes in m³, e.g. 5e-4 for half a litre of hose</source>
        <translation>volúmenes en m³, p. ej. 5e-4 para medio litro de manguera</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the spool's time constant in seconds, e.g. TAU 0.05</source>
        <translation>la constante de tiempo de la corredera en segundos, p. ej. TAU 0.05</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give its magnitude in SI units</source>
        <translation>indique su magnitud en unidades SI</translation>
    </message>
    <message>
        <location line="+26" />
        <source>the force id</source>
        <translation>el id de la fuerza</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the force kind is missing</source>
        <translation>%1: falta el tipo de fuerza</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write POINT, TORQUE, JOINT, SPRING or AERO after the force id</source>
        <translation>escriba POINT, TORQUE, JOINT, SPRING o AERO después del id de la fuerza</translation>
    </message>
    <message>
        <location line="+6" />
        <source>coefficient</source>
        <translation>coeficiente</translation>
    </message>
    <message>
        <location line="+13" />
        <source>stiffness</source>
        <translation>rigidez</translation>
    </message>
    <message>
        <location line="+1" />
        <source>length</source>
        <translation>longitud</translation>
    </message>
    <message>
        <location line="+1" />
        <source>damping</source>
        <translation>amortiguamiento</translation>
    </message>
    <message>
        <location line="+3" />
        <source>area</source>
        <translation>área</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+96" />
        <source>density</source>
        <translation>densidad</translation>
    </message>
    <message>
        <location line="-59" />
        <source>%1: unknown force kind '%2'</source>
        <translation>%1: tipo de fuerza desconocido '%2'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>force kinds are POINT, TORQUE, JOINT, SPRING and AERO</source>
        <translation>los tipos de fuerza son POINT, TORQUE, JOINT, SPRING y AERO</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a %1 force</source>
        <translation>una fuerza %1</translation>
    </message>
    <message>
        <location line="+38" />
        <source>graphic</source>
        <translation>gráfico</translation>
    </message>
    <message>
        <location line="+0" />
        <source>the graphic id</source>
        <translation>el id del gráfico</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: B body is missing after the id</source>
        <translation>%1: falta B cuerpo después del id</translation>
    </message>
    <message>
        <location line="+10" />
        <source>mass</source>
        <translation>masa</translation>
    </message>
    <message>
        <location line="+3" />
        <source>factor</source>
        <translation>factor</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1: the shape is missing</source>
        <translation>%1: falta la forma</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH and its dimensions</source>
        <translation>escriba BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM o MESH y sus dimensiones</translation>
    </message>
    <message>
        <location line="+25" />
        <source>%1: unknown shape '%2'</source>
        <translation>%1: forma desconocida '%2'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>shapes are BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM and MESH</source>
        <translation>las formas son BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM y MESH</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1 dimension %2 of %3 (%4)</source>
        <translation>la dimensión %2 de %3 de %1 (%4)</translation>
    </message>
    <message>
        <location line="+12" />
        <source>a PRISM value</source>
        <translation>un valor de PRISM</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: PRISM needs its height H and at least three x y vertices, found %2 numbers</source>
        <translation>%1: PRISM necesita su altura H y al menos tres vértices x y; se encontraron %2 números</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: the MESH file name must be in double quotes</source>
        <translation>%1: el nombre del archivo de MESH debe ir entre comillas dobles</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: MESH needs a file name in double quotes</source>
        <translation>%1: MESH necesita un nombre de archivo entre comillas dobles</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write MESH "meshes/part.stl" (relative to the model file)</source>
        <translation>escriba MESH "meshes/part.stl" (relativo al archivo de modelo)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a graphic (G)</source>
        <translation>un gráfico (G)</translation>
    </message>
    <message>
        <location line="+16" />
        <source>%1: give MASS or RHO, not both</source>
        <translation>%1: indique MASS o RHO, no ambos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MASS is the solid's mass in kg; RHO its density in kg/m³</source>
        <translation>MASS es la masa del sólido en kg; RHO, su densidad en kg/m³</translation>
    </message>
    <message>
        <location filename="../solver/integrate/integrator.cpp" line="+73" />
        <source>the right-hand side reported a failure at t = %1 s</source>
        <translation>el lado derecho de las ecuaciones informó una falla en t = %1 s</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the right-hand side gave a non-finite value in component %1 (%2) at t = %3 s</source>
        <translation>el lado derecho de las ecuaciones dio un valor no finito en la componente %1 (%2) en t = %3 s</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the right-hand side threw an exception at t = %1 s</source>
        <translation>el lado derecho de las ecuaciones lanzó una excepción en t = %1 s</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the event functions reported a failure at t = %1 s</source>
        <translation>las funciones de evento informaron una falla en t = %1 s</translation>
    </message>
    <message>
        <location line="+3" />
        <source>event function %1 is not finite (%2) at t = %3 s</source>
        <translation>la función de evento %1 no es finita (%2) en t = %3 s</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the event functions threw an exception at t = %1 s</source>
        <translation>las funciones de evento lanzaron una excepción en t = %1 s</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1 at t = %2 s</source>
        <translation>%1 en t = %2 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 at t = %2 s [%3]</source>
        <translation>%1 en t = %2 s [%3]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 at t = %2 s: %3</source>
        <translation>%1 en t = %2 s: %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 at t = %2 s: %3 [%4]</source>
        <translation>%1 en t = %2 s: %3 [%4]</translation>
    </message>
    <message>
        <location filename="../solver/integrate/simulation.cpp" line="-1" />
        <source>the ground</source>
        <translation>tierra</translation>
    </message>
    <message>
        <location line="+2" />
        <source>body %1 %2</source>
        <translation>cuerpo %1 %2</translation>
    </message>
    <message>
        <location line="+23" />
        <source>t=%1 s: %2 welded to %3</source>
        <translation>t=%1 s: %2 soldado a %3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>t=%1 s: %2 released from %3</source>
        <translation>t=%1 s: %2 liberado de %3</translation>
    </message>
    <message>
        <location line="+5" />
        <source>t=%1 s: pump %2 saturated: the valves ask for %3 L/min, more than it gives</source>
        <translation>t=%1 s: bomba %2 saturada: las válvulas piden %3 L/min, más de lo que entrega</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: pump %2 no longer saturated (%3 L/min asked)</source>
        <translation>t=%1 s: la bomba %2 ya no está saturada (se piden %3 L/min)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>t=%1 s: joint %2 cavitates: a chamber's pressure fell to 0 (the load runs ahead of the oil)</source>
        <translation>t=%1 s: la articulación %2 cavita: la presión de una cámara cayó a 0 (la carga se adelanta al aceite)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>t=%1 s: joint %2 no longer cavitates</source>
        <translation>t=%1 s: la articulación %2 ya no cavita</translation>
    </message>
    <message>
        <location line="+13" />
        <source>t=%1 s: %2 and %3 overlap by %4 mm, deeper than the contact pushes back for (a drive stronger than the contact, or a fast hit): they are pushed apart gently</source>
        <translation>t=%1 s: %2 y %3 se traslapan %4 mm, más de lo que el contacto alcanza a rechazar (un accionamiento más fuerte que el contacto, o un golpe rápido): se separan suavemente</translation>
    </message>
    <message>
        <location line="+3" />
        <source>t=%1 s: %2 and %3 no longer overlap deeply (%4 mm)</source>
        <translation>t=%1 s: %2 y %3 ya no se traslapan en profundidad (%4 mm)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>t=%1 s: the closed loops (closing joints %2) locked up: a singular configuration, the mechanism cannot move on</source>
        <translation>t=%1 s: los lazos cerrados (articulaciones de cierre %2) se trabaron: una configuración singular, el mecanismo no puede seguir moviéndose</translation>
    </message>
    <message>
        <location line="+19" />
        <source>t=%1 s: joint %2 hit its lower limit %3 %4</source>
        <translation>t=%1 s: la articulación %2 llegó a su límite inferior %3 %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: joint %2 hit its upper limit %3 %4</source>
        <translation>t=%1 s: la articulación %2 llegó a su límite superior %3 %4</translation>
    </message>
    <message>
        <location line="+3" />
        <source>t=%1 s: joint %2 left its lower limit %3 %4</source>
        <translation>t=%1 s: la articulación %2 dejó su límite inferior %3 %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: joint %2 left its upper limit %3 %4</source>
        <translation>t=%1 s: la articulación %2 dejó su límite superior %3 %4</translation>
    </message>
    <message>
        <location line="+3" />
        <source>t=%1 s: joint %2 relief valve opened extending at %3 %4</source>
        <translation>t=%1 s: articulación %2: la válvula de alivio se abrió al extender, a %3 %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: joint %2 relief valve opened retracting at %3 %4</source>
        <translation>t=%1 s: articulación %2: la válvula de alivio se abrió al retraer, a %3 %4</translation>
    </message>
    <message>
        <location line="+3" />
        <source>t=%1 s: joint %2 relief valve closed extending</source>
        <translation>t=%1 s: articulación %2: la válvula de alivio se cerró al extender</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: joint %2 relief valve closed retracting</source>
        <translation>t=%1 s: articulación %2: la válvula de alivio se cerró al retraer</translation>
    </message>
    <message>
        <location line="+823" />
        <source>the closed loops locked up at t = %1 s (a singular configuration: the loop-closure equations lost rank, so the mechanism cannot move on there); drive it another way or change the geometry</source>
        <translation>los lazos cerrados se trabaron en t = %1 s (una configuración singular: las ecuaciones de cierre de los lazos perdieron rango, así que el mecanismo no puede seguir moviéndose desde ahí); accione el mecanismo de otra forma o cambie la geometría</translation>
    </message>
    <message>
        <location line="+30" />
        <source>the likely cause: spring force %1 (K = %2 N/m on a body of %3 kg, a natural period of %4 s) is too stiff for the step of %5 s; use a step under %6 s or the adaptive integrator, or soften the spring</source>
        <translation>la causa probable: la fuerza de resorte %1 (K = %2 N/m sobre un cuerpo de %3 kg, un período natural de %4 s) es demasiado rígida para el paso de %5 s; use un paso menor que %6 s o el integrador adaptativo, o ablande el resorte</translation>
    </message>
    <message>
        <location line="+10" />
        <source>the likely cause: a spring, force or hydraulic drive too stiff for the step of %1 s, or a body too light for the forces on it; try a smaller step or the adaptive integrator, and check the masses and force magnitudes</source>
        <translation>la causa probable: un resorte, una fuerza o un accionamiento hidráulico demasiado rígido para el paso de %1 s, o un cuerpo demasiado liviano para las fuerzas que recibe; pruebe un paso menor o el integrador adaptativo, y revise las masas y las magnitudes de las fuerzas</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the likely cause: a force or spring that grows without bound, or a body too light for the forces on it; check the masses and force magnitudes</source>
        <translation>la causa probable: una fuerza o un resorte que crece sin límite, o un cuerpo demasiado liviano para las fuerzas que recibe; revise las masas y las magnitudes de las fuerzas</translation>
    </message>
    <message>
        <location line="+39" />
        <source>the closed loops cannot be closed at t = %1 s from the coordinates given: set coordinates the loops can reach</source>
        <translation>los lazos cerrados no se pueden cerrar en t = %1 s con las coordenadas indicadas: indique coordenadas que los lazos puedan alcanzar</translation>
    </message>
    <message>
        <location line="+33" />
        <source>the simulation failed at t = %1 s: the pressures of the drive on joint %2 are no longer finite (%3); check its volumes, valve and pump data</source>
        <translation>la simulación falló en t = %1 s: las presiones del accionamiento de la articulación %2 dejaron de ser finitas (%3); revise los datos de sus volúmenes, de su válvula y de su bomba</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the simulation failed at t = %1 s: %2</source>
        <translation>la simulación falló en t = %1 s: %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the simulation failed at t = %1 s, joint %2: %3; %4</source>
        <translation>la simulación falló en t = %1 s, articulación %2: %3; %4</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the simulation failed at t = %1 s, joint %2 (%3): %4; %5</source>
        <translation>la simulación falló en t = %1 s, articulación %2 (%3): %4; %5</translation>
    </message>
    <message>
        <location line="+53" />
        <source>more than %1 events before t = %2 s: the joints keep switching (chattering)</source>
        <translation>más de %1 eventos antes de t = %2 s: las articulaciones no dejan de conmutar (chattering)</translation>
    </message>
    <message>
        <location line="+49" />
        <source>cannot weld: no such body</source>
        <translation>no se puede soldar: no existe ese cuerpo</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot weld %1 to itself</source>
        <translation>no se puede soldar el %1 a sí mismo</translation>
    </message>
    <message>
        <location line="+5" />
        <source>cannot weld %1 to %2: %3 is already welded (release that weld first)</source>
        <translation>no se puede soldar el %1 a %2: el %3 ya está soldado (libere primero esa soldadura)</translation>
    </message>
    <message>
        <location line="+36" />
        <source>cannot release: %1 is not welded to %2</source>
        <translation>no se puede liberar: el %1 no está soldado a %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>cannot release: no such body</source>
        <translation>no se puede liberar: no existe ese cuerpo</translation>
    </message>
    <message>
        <location filename="../solver/core/output_file.cpp" line="+40" />
        <location filename="../solver/io/csv_writer.cpp" line="+36" />
        <source>no output file given</source>
        <translation>no se indicó ningún archivo de salida</translation>
    </message>
    <message>
        <location line="+2" />
        <source>cannot write %1: it is a folder</source>
        <translation>no se puede escribir %1: es una carpeta</translation>
    </message>
    <message>
        <location line="+9" />
        <source>cannot write %1: it is %2, which this run reads; give another output file</source>
        <translation>no se puede escribir %1: es %2, que esta ejecución lee; indique otro archivo de salida</translation>
    </message>
    <message>
        <location line="+45" />
        <location line="+6" />
        <location line="+13" />
        <source>cannot create %1: %2</source>
        <translation>no se puede crear %1: %2</translation>
    </message>
    <message>
        <location filename="../solver/io/csv_writer.cpp" line="+38" />
        <location line="+72" />
        <source>cannot write to standard output: %1</source>
        <translation>no se puede escribir en la salida estándar: %1</translation>
    </message>
    <message>
        <location filename="../solver/core/output_file.cpp" line="-34" />
        <location line="+41" />
        <location line="+3" />
        <location line="+6" />
        <location line="+1" />
        <location line="+5" />
        <location line="+14" />
        <location line="+4" />
        <location line="+3" />
        <location line="+8" />
        <location line="+23" />
        <location filename="../solver/io/csv_writer.cpp" line="-71" />
        <source>cannot write %1: %2</source>
        <translation>no se puede escribir %1: %2</translation>
    </message>
    <message>
        <location filename="../solver/io/csv_writer.cpp" line="+8" />
        <source>the header was written in the middle of a row</source>
        <translation>el encabezado se escribió en medio de una fila</translation>
    </message>
    <message>
        <location line="+33" />
        <source>a row has %1 values; the header has %2 columns</source>
        <translation>una fila tiene %1 valores; el encabezado tiene %2 columnas</translation>
    </message>
    <message>
        <location filename="../solver/core/output_file.cpp" line="-69" />
        <location filename="../solver/io/csv_writer.cpp" line="+21" />
        <source>the output was already closed</source>
        <translation>la salida ya estaba cerrada</translation>
    </message>
    <message>
        <location filename="../solver/io/csv_writer.cpp" line="+4" />
        <source>the last row is not finished</source>
        <translation>la última fila no está terminada</translation>
    </message>
    <message>
        <location filename="../solver/contact/contact_geometry.cpp" line="+127" />
        <source>G %1 cannot serve as a contact shape: %2</source>
        <translation>G %1 no puede servir como forma de contacto: %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>fix the mesh file, or mark the graphic NOCONTACT (drawn only)</source>
        <translation>corrija el archivo de malla, o marque el gráfico NOCONTACT (solo se dibuja)</translation>
    </message>
    <message>
        <location line="+57" />
        <source>G %1 and %2 overlap by %3 mm at the initial pose: they never touch each other</source>
        <translation>G %1 y %2 se traslapan %3 mm en la pose inicial: nunca se tocan entre sí</translation>
    </message>
    <message>
        <location line="+3" />
        <location filename="../solver/integrate/simulation.cpp" line="-1155" />
        <source>scene G %1</source>
        <translation>G %1 de la escena</translation>
    </message>
    <message>
        <location line="+0" />
        <location filename="../solver/integrate/simulation.cpp" line="+0" />
        <source>G %1</source>
        <translation>G %1</translation>
    </message>
    <message>
        <location line="+7" />
        <source>a pin in its bore is meant to; solids placed inside each other by mistake: move one out</source>
        <translation>un pasador en su alojamiento debe hacerlo; si los sólidos quedaron uno dentro del otro por error, saque uno</translation>
    </message>
    <message>
        <location line="+4" />
        <source>these solids are not joined to each other: they start inside each other and will pass through each other; move one out (or mark one NOCONTACT if it is only drawn)</source>
        <translation>estos sólidos no están unidos entre sí: parten uno dentro del otro y se atravesarán; saque uno (o márquelo NOCONTACT si solo se dibuja)</translation>
    </message>
</context>
<context>
    <name>DriveControls</name>
    <message>
        <location filename="../ide/studio/train/drive_controls.cpp" line="+35" />
        <source>left stick right + / left −</source>
        <translation>stick izquierdo a la derecha + / a la izquierda −</translation>
    </message>
    <message>
        <location line="+0" />
        <source>left stick left + / right −</source>
        <translation>stick izquierdo a la izquierda + / a la derecha −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>left stick up + / down −</source>
        <translation>stick izquierdo arriba + / abajo −</translation>
    </message>
    <message>
        <location line="+0" />
        <source>left stick down + / up −</source>
        <translation>stick izquierdo abajo + / arriba −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>right stick right + / left −</source>
        <translation>stick derecho a la derecha + / a la izquierda −</translation>
    </message>
    <message>
        <location line="+0" />
        <source>right stick left + / right −</source>
        <translation>stick derecho a la izquierda + / a la derecha −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>right stick up + / down −</source>
        <translation>stick derecho arriba + / abajo −</translation>
    </message>
    <message>
        <location line="+0" />
        <source>right stick down + / up −</source>
        <translation>stick derecho abajo + / arriba −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>left trigger +</source>
        <translation>gatillo izquierdo +</translation>
    </message>
    <message>
        <location line="+0" />
        <source>left trigger −</source>
        <translation>gatillo izquierdo −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>right trigger +</source>
        <translation>gatillo derecho +</translation>
    </message>
    <message>
        <location line="+0" />
        <source>right trigger −</source>
        <translation>gatillo derecho −</translation>
    </message>
    <message>
        <location line="+3" />
        <source>gamepad axis %1</source>
        <translation>eje %1 del mando</translation>
    </message>
    <message>
        <location line="+13" />
        <source>+ closes / − opens</source>
        <translation>+ cierra / − abre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>+ opens / − closes</source>
        <translation>+ abre / − cierra</translation>
    </message>
    <message>
        <location line="+17" />
        <source>+ up / − down</source>
        <translation>+ sube / − baja</translation>
    </message>
    <message>
        <location line="+0" />
        <source>+ down / − up</source>
        <translation>+ baja / − sube</translation>
    </message>
    <message>
        <location line="+6" />
        <source>+ out / − in</source>
        <translation>+ sale / − entra</translation>
    </message>
    <message>
        <location line="+0" />
        <source>+ in / − out</source>
        <translation>+ entra / − sale</translation>
    </message>
    <message>
        <location line="+2" />
        <source>+ right / − left</source>
        <translation>+ a la derecha / − a la izquierda</translation>
    </message>
    <message>
        <location line="+0" />
        <source>+ left / − right</source>
        <translation>+ a la izquierda / − a la derecha</translation>
    </message>
    <message>
        <location line="+12" />
        <source>%1 + / %2 −</source>
        <comment>the key giving the drive +, the one giving −</comment>
        <translation>%1 + / %2 −</translation>
    </message>
    <message>
        <location line="+4" />
        <source>joystick axis %1</source>
        <translation>eje %1 del joystick</translation>
    </message>
    <message>
        <location line="+0" />
        <source>joystick axis %1 reversed</source>
        <translation>eje %1 del joystick, invertido</translation>
    </message>
    <message>
        <location line="+3" />
        <source>lever %1</source>
        <translation>palanca %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>lever %1 reversed</source>
        <translation>palanca %1 invertida</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 (bank %2)</source>
        <translation>%1 (banco %2)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 (%2)</source>
        <comment>a drive and which way + moves it</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source>no control</source>
        <translation>ningún mando</translation>
    </message>
</context>
<context>
    <name>StationNode</name>
    <message>
        <location filename="../trainer/centre/station_node.cpp" line="+41" />
        <source>A station needs at least one tutorial to run.</source>
        <translation>Una estación necesita al menos un tutorial que ejecutar.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>A station needs a name, unique in the centre.</source>
        <translation>Una estación necesita un nombre, único en el centro.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The tutorials of one station must all use the same model: %1 uses %2, %3 uses %4.</source>
        <translation>Los tutoriales de una estación deben usar todos el mismo modelo: %1 usa %2, %3 usa %4.</translation>
    </message>
    <message>
        <location line="+105" />
        <source>the records journal takes writes again</source>
        <translation>el registro local vuelve a aceptar escrituras</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the records journal refuses writes: %1</source>
        <translation>el registro local rechaza escrituras: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+3" />
        <source>%n pending attempt(s) recorded in the journal</source>
        <translation>
            <numerusform>%n intento pendiente incorporado al registro local</numerusform>
            <numerusform>%n intentos pendientes incorporados al registro local</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TutorialRunner</name>
    <message>
        <location filename="../trainer/training/runner.cpp" line="+46" />
        <source>Autopilot console</source>
        <translation>Consola del piloto automático</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lever %1</source>
        <translation>Palanca %1</translation>
    </message>
    <message>
        <location line="+146" />
        <source>line %1: %2</source>
        <translation>línea %1: %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>expected id=value, found "%1"</source>
        <translation>se esperaba id=valor, hay "%1"</translation>
    </message>
    <message>
        <location line="+7" />
        <source>"%1" is not a joint id</source>
        <translation>"%1" no es un id de articulación</translation>
    </message>
    <message>
        <location line="+10" />
        <source>"%1" is not a number</source>
        <translation>"%1" no es un número</translation>
    </message>
    <message>
        <location line="+2" />
        <source>wait must not be negative</source>
        <translation>wait no puede ser negativo</translation>
    </message>
    <message>
        <location line="+3" />
        <source>tol must be greater than 0</source>
        <translation>tol debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>ramp must be greater than 0</source>
        <translation>ramp debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>stall must be greater than 0</source>
        <translation>stall debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>lever must be greater than 0 and at most 1</source>
        <translation>lever debe ser mayor que 0 y a lo sumo 1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>"%1" is not a joint id, wait, tol, lever, ramp or stall</source>
        <translation>"%1" no es un id de articulación, wait, tol, lever, ramp ni stall</translation>
    </message>
    <message>
        <location line="+5" />
        <source>line %1: lever=, ramp= and stall= go with joint targets</source>
        <translation>línea %1: lever=, ramp= y stall= van con objetivos de articulaciones</translation>
    </message>
    <message>
        <location line="+49" />
        <location line="+7" />
        <source>line %1: the model has no joint %2</source>
        <translation>línea %1: el modelo no tiene la articulación %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>line %1: the profile "%2" gives joint %3 no lever of a serial console</source>
        <translation>línea %1: el perfil "%2" no le asigna a la articulación %3 ninguna palanca de una consola serie</translation>
    </message>
    <message>
        <location line="+4" />
        <source>line %1: joint %2's drive is not enabled in this tutorial</source>
        <translation>línea %1: el accionamiento de la articulación %2 no está habilitado en este tutorial</translation>
    </message>
</context>
<context>
    <name>TutorialSession</name>
    <message>
        <location filename="../trainer/training/session.cpp" line="+77" />
        <source>Goal done</source>
        <translation>Objetivo cumplido</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Grasp</source>
        <translation>Agarre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Missed grasp</source>
        <translation>Agarre fallido</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Release</source>
        <translation>Soltar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Load dropped</source>
        <translation>Caída de la carga</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hit</source>
        <translation>Golpe</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hard hit</source>
        <translation>Golpe fuerte</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Near miss</source>
        <translation>Casi choque</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Worker's safety zone</source>
        <translation>Zona de seguridad del trabajador</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Worker hit</source>
        <translation>Trabajador golpeado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Overload</source>
        <translation>Sobrecarga</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Limit bang</source>
        <translation>Golpe en el tope</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pump saturated</source>
        <translation>Bomba saturada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cavitation</source>
        <translation>Cavitación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Time up</source>
        <translation>Tiempo agotado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Input ended</source>
        <translation>Fin de la entrada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Simulation stopped</source>
        <translation>Simulación detenida</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Instructor</source>
        <translation>Instructor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <location line="+75" />
        <source>Goal done: %1</source>
        <translation>Objetivo cumplido: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The load is in the claws</source>
        <translation>La carga está en las garras</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The claws closed %1 m away from the grip</source>
        <translation>Las garras se cerraron a %1 m del punto de agarre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The load was released</source>
        <translation>Se soltó la carga</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The load was released out of place and fell</source>
        <translation>La carga se soltó fuera de lugar y cayó</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Touched %1 at %2 m/s</source>
        <translation>Tocó %1 a %2 m/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hit %1 hard, at %2 m/s: the attempt ends</source>
        <translation>Golpe fuerte contra %1, a %2 m/s: el intento termina</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Passed %1 m from %2</source>
        <translation>Pasó a %1 m de %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Entered the safety zone of %1 (%2 m)</source>
        <translation>Entró en la zona de seguridad de %1 (%2 m)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Touched %1: the attempt ends</source>
        <translation>Tocó a %1: el intento termina</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Relief valve of %1 opened (%2 kN)</source>
        <translation>Se abrió la válvula de alivio de %1 (%2 kN)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 hit its end stop at full speed</source>
        <translation>%1 golpeó su tope a toda velocidad</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The pump %1 could not give the %2 L/min the levers asked for: every function slowed</source>
        <translation>La bomba %1 no pudo entregar los %2 L/min que pedían las palancas: todas las funciones se hicieron más lentas</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 ran ahead of the oil: its cylinder cavitated</source>
        <translation>%1 se adelantó al aceite: su cilindro cavitó</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The time limit was reached</source>
        <translation>Se alcanzó el tiempo límite</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The recorded input ended before the goals were done</source>
        <translation>La entrada grabada terminó antes de cumplir los objetivos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The simulation stopped: %1</source>
        <translation>La simulación se detuvo: %1</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Instructor %1 started the attempt</source>
        <translation>El instructor %1 inició el intento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1 paused the attempt</source>
        <translation>El instructor %1 pausó el intento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1 resumed the attempt</source>
        <translation>El instructor %1 reanudó el intento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1 restarted the tutorial</source>
        <translation>El instructor %1 reinició el tutorial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1 stopped the attempt</source>
        <translation>El instructor %1 detuvo el intento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1: %2</source>
        <translation>Instructor %1: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The attempt was stopped</source>
        <translation>Se detuvo el intento</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Path</source>
        <translation>Trayectoria</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Smoothness</source>
        <translation>Suavidad</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Safety</source>
        <translation>Seguridad</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Work faster: move several valves together once you are sure of the way.</source>
        <translation>Trabaje más rápido: mueva varias válvulas a la vez cuando esté seguro del camino.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Take a straighter way: plan the movement before you start, and avoid going back and forth.</source>
        <translation>Siga un camino más directo: planifique el movimiento antes de empezar y evite ir y volver.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Move the levers gently: open and close the valves gradually so the load does not jerk.</source>
        <translation>Mueva las palancas con suavidad: abra y cierre las válvulas de a poco para que la carga no dé tirones.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Keep clear of the mill, the cart and the people, do not force the cylinders against their relief valves and do not run into the end stops.</source>
        <translation>Manténgase lejos del molino, del carro y de las personas, no fuerce los cilindros contra sus válvulas de alivio y no choque contra los topes.</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Nothing was done towards the goals: drive the machine towards the first one (the start screen names the keys and levers of each drive).</source>
        <translation>No se hizo nada hacia los objetivos: lleve la máquina hacia el primero (la pantalla de inicio indica las teclas y palancas de cada accionamiento).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Complete every goal: the stage is passed only when all are done.</source>
        <translation>Cumpla todos los objetivos: la etapa se aprueba solo cuando están todos cumplidos.</translation>
    </message>
    <message>
        <location line="-150" />
        <source>Fault injected</source>
        <translation>Falla introducida</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fault cleared</source>
        <translation>Falla resuelta</translation>
    </message>
    <message>
        <location filename="../trainer/training/faults.cpp" line="+40" />
        <source>Hose burst</source>
        <translation>Rotura de manguera</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stuck valve</source>
        <translation>Válvula trabada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Worker walks in</source>
        <translation>Entra un trabajador</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Power cut</source>
        <translation>Corte de energía</translation>
    </message>
    <message>
        <location filename="../trainer/training/session.cpp" line="+41" />
        <source>Instructor: the hose of %1 was repaired</source>
        <translation>Instructor: se reparó la manguera de %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor: a hose of %1 burst; the drive has no pressure</source>
        <translation>Instructor: se rompió una manguera de %1; el accionamiento no tiene presión</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Instructor: the valve of %1 was freed</source>
        <translation>Instructor: se liberó la válvula de %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor: the valve of %1 stuck at %2 % of its opening</source>
        <translation>Instructor: la válvula de %1 se trabó al %2 % de su apertura</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Instructor: %1 left the work area</source>
        <translation>Instructor: %1 salió del área de trabajo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor: %1 walked into the work area</source>
        <translation>Instructor: %1 entró al área de trabajo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Instructor: the power is back</source>
        <translation>Instructor: volvió la energía</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor: the power was cut; every valve closed</source>
        <translation>Instructor: se cortó la energía; todas las válvulas se cerraron</translation>
    </message>
    <message>
        <location line="+767" />
        <source>There is no drive "%1": this machine has no hydraulic drives</source>
        <translation>No hay un accionamiento "%1": esta máquina no tiene accionamientos hidráulicos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>There is no drive "%1" on this machine; its hydraulic drives are: %2</source>
        <translation>No hay un accionamiento "%1" en esta máquina; sus accionamientos hidráulicos son: %2</translation>
    </message>
    <message>
        <location line="+54" />
        <source>The attempt has ended: no fault can be injected</source>
        <translation>El intento terminó: no se pueden introducir fallas</translation>
    </message>
    <message>
        <location line="+21" />
        <source>A burst hose's damping and residual force must be zero or more</source>
        <translation>El amortiguamiento y la fuerza residual de una manguera rota deben ser cero o más</translation>
    </message>
    <message>
        <location line="+5" />
        <source>A stuck valve's opening is a command from -1 to 1, not %1</source>
        <translation>La apertura de una válvula trabada es un comando de -1 a 1, no %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>This tutorial has no worker who could walk in (it has no WORKER)</source>
        <translation>Este tutorial no tiene un trabajador que pueda entrar (no tiene WORKER)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>There is no worker %1 in this tutorial: its workers are numbered 0 to %2</source>
        <translation>No hay un trabajador %1 en este tutorial: sus trabajadores van del 0 al %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Worker %1 has no graphics in the scene that could be moved</source>
        <translation>El trabajador %1 no tiene gráficos en la escena que se puedan mover</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The place a worker walks to must be a finite position</source>
        <translation>El lugar al que camina un trabajador debe ser una posición finita</translation>
    </message>
    <message>
        <location line="+18" />
        <source>The attempt has ended: no fault can be cleared</source>
        <translation>El intento terminó: no se pueden resolver fallas</translation>
    </message>
    <message>
        <location line="+23" />
        <source>No hose of %1 has burst</source>
        <translation>No se ha roto ninguna manguera de %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The valve of %1 is not stuck</source>
        <translation>La válvula de %1 no está trabada</translation>
    </message>
    <message>
        <location line="+2" />
        <source>No worker has walked in</source>
        <translation>No ha entrado ningún trabajador</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Worker %1 has not walked in</source>
        <translation>El trabajador %1 no ha entrado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The power has not been cut</source>
        <translation>La energía no se ha cortado</translation>
    </message>
</context>
<context>
    <name>Tutorials</name>
    <message>
        <location filename="../trainer/training/tutorial.cpp" line="+53" />
        <source>%1 has no %2 text</source>
        <translation>%1 no tiene texto %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add %1 "…": every text is in Spanish and English</source>
        <translation>agregue %1 "…": cada texto va en español y en inglés</translation>
    </message>
    <message>
        <location line="+30" />
        <source>a tutorial file</source>
        <translation>un archivo de tutorial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a tutorial is a short text file; check that this is one</source>
        <translation>un tutorial es un archivo de texto corto; revise que este lo sea</translation>
    </message>
    <message>
        <location line="+15" />
        <source>the TITLE</source>
        <translation>el TITLE</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the tutorial has no TITLE</source>
        <translation>el tutorial no tiene TITLE</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add TITLE ES "…" EN "…"</source>
        <translation>agregue TITLE ES "…" EN "…"</translation>
    </message>
    <message>
        <location line="+2" />
        <source>this INTRO</source>
        <translation>este INTRO</translation>
    </message>
    <message>
        <location line="+3" />
        <source>goal '%1' has no NAME</source>
        <translation>el objetivo '%1' no tiene NAME</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add a NAME ES "…" EN "…" line after it: the HUD shows it</source>
        <translation>agregue una línea NAME ES "…" EN "…" a continuación: el HUD la muestra</translation>
    </message>
    <message>
        <location line="+2" />
        <source>goal '%1''s NAME</source>
        <translation>el NAME del objetivo '%1'</translation>
    </message>
    <message>
        <location line="+3" />
        <source>this HINT</source>
        <translation>este HINT</translation>
    </message>
    <message>
        <location line="+3" />
        <source>this PART has no NAME</source>
        <translation>este PART no tiene NAME</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add a NAME ES "…" EN "…" line after it</source>
        <translation>agregue una línea NAME ES "…" EN "…" a continuación</translation>
    </message>
    <message>
        <location line="+2" />
        <source>this PART's NAME</source>
        <translation>el NAME de este PART</translation>
    </message>
    <message>
        <location line="+4" />
        <source>this WORKER's NAME</source>
        <translation>el NAME de este WORKER</translation>
    </message>
    <message>
        <location line="+9" />
        <source>the model '%1' cannot be used (errors above)</source>
        <translation>no se puede usar el modelo '%1' (errores más arriba)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>fix the model, or check the path: it is relative to the tutorial's folder</source>
        <translation>corrija el modelo, o revise la ruta: es relativa a la carpeta del tutorial</translation>
    </message>
    <message>
        <location line="+14" />
        <source>the scene '%1' cannot be used (errors above)</source>
        <translation>no se puede usar la escena '%1' (errores más arriba)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>fix the scene, or check the path: it is relative to the tutorial's folder</source>
        <translation>corrija la escena, o revise la ruta: es relativa a la carpeta del tutorial</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the scene '%1' cannot be used with the model's CONTACT (errors above)</source>
        <translation>la escena '%1' no se puede usar con el CONTACT del modelo (errores arriba)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>mark the scene's graphics that the model must not touch NOCONTACT</source>
        <translation>marque NOCONTACT los gráficos de la escena que el modelo no debe tocar</translation>
    </message>
    <message>
        <location line="+16" />
        <source>%1: the model has no moving body %2</source>
        <translation>%1: el modelo no tiene un cuerpo móvil %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>use a body id of '%1' (not the ground, 0)</source>
        <translation>use un id de cuerpo de '%1' (no el suelo, 0)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1: the model has no joint %2 in its tree</source>
        <translation>%1: el modelo no tiene la articulación %2 en su árbol</translation>
    </message>
    <message>
        <location line="+3" />
        <source>use a joint id (C) of '%1'</source>
        <translation>use un id de articulación (C) de '%1'</translation>
    </message>
    <message>
        <location line="+11" />
        <source>joint %1 has no drive</source>
        <translation>la articulación %1 no tiene accionamiento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>DRIVES lists joints with a D statement in the model</source>
        <translation>DRIVES enumera articulaciones que tienen una instrucción D en el modelo</translation>
    </message>
    <message>
        <location line="+12" />
        <source>joint %1's actuator cannot reach %2</source>
        <translation>el actuador de la articulación %1 no puede alcanzar %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give a length the joint's geometry allows</source>
        <translation>indique un largo que la geometría de la articulación permita</translation>
    </message>
    <message>
        <location line="+5" />
        <source>joint %1's initial value %2 is beyond its limits</source>
        <translation>el valor inicial %2 de la articulación %1 está fuera de sus límites</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give a value between its LL and UL</source>
        <translation>indique un valor entre su LL y su UL</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the load and the tool are the same body</source>
        <translation>la carga y la herramienta son el mismo cuerpo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the tool grips another body</source>
        <translation>la herramienta toma otro cuerpo</translation>
    </message>
    <message>
        <location line="+3" />
        <source>GRIP has no CLAW</source>
        <translation>GRIP no tiene CLAW</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add CLAW joint CLOSE value OPEN value lines after it</source>
        <translation>agregue a continuación líneas CLAW articulación CLOSE valor OPEN valor</translation>
    </message>
    <message>
        <location line="+27" />
        <source>goal '%1' has no JOINT line</source>
        <translation>el objetivo '%1' no tiene línea JOINT</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add JOINT id AT value TOL d lines after it</source>
        <translation>agregue a continuación líneas JOINT id AT valor TOL d</translation>
    </message>
    <message>
        <location line="+8" />
        <source>joint %1 cannot reach %2: beyond its limits</source>
        <translation>la articulación %1 no puede alcanzar %2: está fuera de sus límites</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give a target between the joint's LL and UL</source>
        <translation>indique un valor objetivo entre el LL y el UL de la articulación</translation>
    </message>
    <message>
        <location line="+8" />
        <source>a GRASP goal needs a GRIP statement</source>
        <translation>un objetivo GRASP necesita una instrucción GRIP</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+7" />
        <source>add GRIP LOAD … TOOL … (docs/training.md)</source>
        <translation>agregue GRIP LOAD … TOOL … (docs/training.md)</translation>
    </message>
    <message>
        <location line="-1" />
        <source>a PLACE goal needs a GRIP statement</source>
        <translation>un objetivo PLACE necesita una instrucción GRIP</translation>
    </message>
    <message>
        <location line="+5" />
        <source>goal '%1' places the load before any GRASP goal</source>
        <translation>el objetivo '%1' posiciona la carga antes de cualquier objetivo GRASP</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put a GRASP goal before it</source>
        <translation>ponga un objetivo GRASP antes de él</translation>
    </message>
    <message>
        <location line="+13" />
        <source>HINT names goal '%1', which the tutorial does not have</source>
        <translation>HINT nombra el objetivo '%1', que el tutorial no tiene</translation>
    </message>
    <message>
        <location line="+1" />
        <source>use a GOAL's id</source>
        <translation>use el id de un GOAL</translation>
    </message>
    <message>
        <location line="+23" />
        <source>WORKER needs a SCENE with the person's graphics</source>
        <translation>WORKER necesita una SCENE con los gráficos de la persona</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add SCENE "…"</source>
        <translation>agregue SCENE "…"</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the scene has no graphic G %1</source>
        <translation>la escena no tiene el gráfico G %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>use the G ids of the person in the scene file</source>
        <translation>use los id G de la persona en el archivo de escena</translation>
    </message>
    <message>
        <location line="+10" />
        <source>PART SCENE needs a SCENE</source>
        <translation>PART SCENE necesita una SCENE</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add SCENE "…", or write PART MODEL for the model's graphics</source>
        <translation>agregue SCENE "…", o escriba PART MODEL para los gráficos del modelo</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the scene has no ground graphic G %1</source>
        <translation>la escena no tiene el gráfico fijo al suelo G %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the model has no ground graphic G %1</source>
        <translation>el modelo no tiene el gráfico fijo al suelo G %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>use the G ids (on body 0) of the part</source>
        <translation>use los id G (en el cuerpo 0) de la pieza</translation>
    </message>
    <message>
        <location line="+12" />
        <source>the station profile '%1' cannot be used: %2</source>
        <translation>no se puede usar el perfil del puesto '%1': %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>name one of the model's profiles or give a .json file relative to the tutorial</source>
        <translation>nombre uno de los perfiles del modelo o indique un archivo .json relativo al tutorial</translation>
    </message>
    <message>
        <location line="+14" />
        <source>goal '%1' cannot be reached with the enabled drives: the nearest pose misses it by %2 m and %3°</source>
        <translation>el objetivo '%1' no se puede alcanzar con los accionamientos habilitados: la postura más cercana queda a %2 m y %3° de él</translation>
    </message>
    <message>
        <location line="+5" />
        <source>move the target within reach, enable more DRIVES or widen TOL/ANGTOL</source>
        <translation>ponga el destino al alcance, habilite más DRIVES o amplíe TOL/ANGTOL</translation>
    </message>
    <message>
        <location line="+12" />
        <source>the demonstration cannot be used: %1</source>
        <translation>no se puede usar la demostración: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>record it again (Train ▸ Record demonstration) or fix the path</source>
        <translation>grábela de nuevo (Entrenar ▸ Grabar demostración) o corrija la ruta</translation>
    </message>
    <message>
        <location line="+9" />
        <source>the demonstration's camera path cannot be used: %1</source>
        <translation>no se puede usar el recorrido de cámara de la demostración: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>record the demonstration again, or remove CAMERA: the viewer's own camera is used</source>
        <translation>grabe la demostración de nuevo, o quite CAMERA: se usa la cámara propia del visor</translation>
    </message>
    <message>
        <location filename="../trainer/training/tutorial_parser.cpp" line="+71" />
        <source>expected %1 %2</source>
        <translation>se esperaba %1 %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write %1 followed by its value</source>
        <translation>escriba %1 seguido de su valor</translation>
    </message>
    <message>
        <location line="+7" />
        <source>expected %1, found the end of the line</source>
        <translation>se esperaba %1, pero la línea terminó</translation>
    </message>
    <message>
        <location line="+1" />
        <source>expected %1, found '%2'</source>
        <translation>se esperaba %1, se encontró '%2'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a number such as 0.5</source>
        <translation>escriba un número como 0.5</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: '%2' is not a finite number</source>
        <translation>%1: '%2' no es un número finito</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: '%2' is too large for a number</source>
        <translation>%1: '%2' es demasiado grande para un número</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a number within ±1e308; check the units</source>
        <translation>escriba un número dentro de ±1e308; revise las unidades</translation>
    </message>
    <message>
        <location line="+6" />
        <source>decimals take a point, not a comma: %1</source>
        <translation>los decimales llevan punto, no coma: %1</translation>
    </message>
    <message>
        <location line="+18" />
        <source>%1 must be a whole number</source>
        <translation>%1 debe ser un número entero</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write it without decimals</source>
        <translation>escríbalo sin decimales</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1 (three numbers: x y z)</source>
        <translation>%1 (tres números: x y z)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1 is the zero vector</source>
        <translation>%1 es el vector nulo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give a direction, e.g. 0 0 1</source>
        <translation>indique una dirección, p. ej. 0 0 1</translation>
    </message>
    <message>
        <location line="+9" />
        <source>expected %1 in double quotes</source>
        <translation>se esperaba %1 entre comillas dobles</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write it as "…"</source>
        <translation>escríbalo como "…"</translation>
    </message>
    <message>
        <location line="+26" />
        <source>the text is given twice in %1</source>
        <translation>el texto aparece dos veces en %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>keep one</source>
        <translation>deje uno solo</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the %1 text</source>
        <translation>el texto %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>expected the text in each language: ES "…" EN "…"</source>
        <translation>se esperaba el texto en cada idioma: ES "…" EN "…"</translation>
    </message>
    <message>
        <location line="+1" />
        <source>every text a person reads is written in Spanish and English</source>
        <translation>todo texto que lee una persona se escribe en español y en inglés</translation>
    </message>
    <message>
        <location line="+6" />
        <source>unexpected '%1' here</source>
        <translation>'%1' inesperado aquí</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove it, or check the statement's keywords in docs/training.md</source>
        <translation>elimínelo, o revise las palabras clave de la instrucción en docs/training.md</translation>
    </message>
    <message>
        <location line="+18" />
        <source>%1 must not be negative</source>
        <translation>%1 no debe ser menor que 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 must be greater than 0</source>
        <translation>%1 debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give a positive value</source>
        <translation>indique un valor positivo</translation>
    </message>
    <message>
        <location line="+35" />
        <source>%1 is given twice</source>
        <translation>%1 aparece dos veces</translation>
    </message>
    <message>
        <location line="+1" />
        <source>keep one %1 statement</source>
        <translation>deje una sola instrucción %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 belongs to a GOAL and must follow it</source>
        <translation>%1 pertenece a un GOAL y debe ir después de él</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put it on the lines after its GOAL statement</source>
        <translation>póngalo en las líneas que siguen a su instrucción GOAL</translation>
    </message>
    <message>
        <location line="+9" />
        <source>the tutorial's id, e.g. T0</source>
        <translation>el id del tutorial, p. ej. T0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the level</source>
        <translation>el nivel</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the station profile's name or file</source>
        <translation>el nombre o el archivo del perfil del puesto</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the file's path</source>
        <translation>la ruta del archivo</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the demonstration's input log</source>
        <translation>el registro de entradas de la demostración</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the demonstration's camera path</source>
        <translation>el recorrido de cámara de la demostración</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a drive's joint id</source>
        <translation>el id de articulación de un accionamiento</translation>
    </message>
    <message>
        <location line="+2" />
        <source>DRIVES lists no drive</source>
        <translation>DRIVES no enumera ningún accionamiento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write the joint ids of the drives the operator may use</source>
        <translation>escriba los id de articulación de los accionamientos que el operador puede usar</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+175" />
        <source>the joint id</source>
        <translation>el id de la articulación</translation>
    </message>
    <message>
        <location line="-174" />
        <source>the joint's initial value</source>
        <translation>el valor inicial de la articulación</translation>
    </message>
    <message>
        <location line="+5" />
        <source>(TIME LIMIT seconds PAR seconds)</source>
        <translation>(TIME LIMIT segundos PAR segundos)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the time limit [s]</source>
        <translation>el tiempo límite [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the time limit</source>
        <translation>el tiempo límite</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(the time that earns every time point)</source>
        <translation>(el tiempo que otorga todos los puntos de tiempo)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the par time [s]</source>
        <translation>el tiempo de referencia [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the par time</source>
        <translation>el tiempo de referencia</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the par time is longer than the time limit</source>
        <translation>el tiempo de referencia es mayor que el tiempo límite</translation>
    </message>
    <message>
        <location line="+1" />
        <source>make PAR at most LIMIT</source>
        <translation>haga que PAR no supere a LIMIT</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the pass mark (0–100)</source>
        <translation>el puntaje de aprobación (0–100)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the pass mark must be between 0 and 100</source>
        <translation>el puntaje de aprobación debe estar entre 0 y 100</translation>
    </message>
    <message>
        <location line="+1" />
        <source>e.g. PASS 60</source>
        <translation>p. ej. PASS 60</translation>
    </message>
    <message>
        <location line="+6" />
        <source>(WEIGHTS TIME a PATH b SMOOTH c SAFETY d)</source>
        <translation>(WEIGHTS TIME a PATH b SMOOTH c SAFETY d)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the time weight</source>
        <translation>el peso del tiempo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the path weight</source>
        <translation>el peso de la trayectoria</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the smoothness weight</source>
        <translation>el peso de la suavidad</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the safety weight</source>
        <translation>el peso de la seguridad</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a weight is negative</source>
        <translation>un peso es negativo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>weights are points, 0 or more</source>
        <translation>los pesos son puntos, 0 o más</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the reference RMS jerk [m/s³]</source>
        <translation>el tirón RMS de referencia [m/s³]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the reference jerk</source>
        <translation>el tirón de referencia</translation>
    </message>
    <message>
        <location line="+3" />
        <source>(TRACK BODY id POINT x y z)</source>
        <translation>(TRACK BODY id POINT x y z)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+69" />
        <source>the body id</source>
        <translation>el id del cuerpo</translation>
    </message>
    <message>
        <location line="-67" />
        <location line="+69" />
        <source>the point on the body</source>
        <translation>el punto en el cuerpo</translation>
    </message>
    <message>
        <location line="-62" />
        <source>(GRIP LOAD body AT x y z TOOL body AT x y z TOL d ANGTOL a)</source>
        <translation>(GRIP LOAD cuerpo AT x y z TOOL cuerpo AT x y z TOL d ANGTOL a)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the load's body id</source>
        <translation>el id del cuerpo de la carga</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(the grip point on the load, in its frame)</source>
        <translation>(el punto de agarre en la carga, en su sistema de referencia)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the grip point on the load</source>
        <translation>el punto de agarre en la carga</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(the body that grips)</source>
        <translation>(el cuerpo que toma la carga)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the tool's body id</source>
        <translation>el id del cuerpo de la herramienta</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(the grip point on the tool, in its frame)</source>
        <translation>(el punto de agarre en la herramienta, en su sistema de referencia)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the grip point on the tool</source>
        <translation>el punto de agarre en la herramienta</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(how close the two grip points must be [m])</source>
        <translation>(qué tan cerca deben estar los dos puntos de agarre [m])</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the grip's position tolerance [m]</source>
        <translation>la tolerancia de posición del agarre [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the grip's tolerance</source>
        <translation>la tolerancia del agarre</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(how far the load's attitude may be from the tool's)</source>
        <translation>(cuánto puede diferir la orientación de la carga de la de la herramienta)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+1" />
        <source>the grip's angle tolerance</source>
        <translation>la tolerancia angular del agarre</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the load's rotation axis in the tool frame</source>
        <translation>el eje de rotación de la carga en el sistema de referencia de la herramienta</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the rotation angle</source>
        <translation>el ángulo de rotación</translation>
    </message>
    <message>
        <location line="+6" />
        <source>CLAW belongs to GRIP and must follow it</source>
        <translation>CLAW pertenece a GRIP y debe ir después de él</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put the CLAW lines after the GRIP statement</source>
        <translation>ponga las líneas CLAW después de la instrucción GRIP</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the claw's joint id</source>
        <translation>el id de articulación de la garra</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(CLAW joint CLOSE value OPEN value)</source>
        <translation>(CLAW articulación CLOSE valor OPEN valor)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the value past which the claw is closed</source>
        <translation>el valor a partir del cual la garra está cerrada</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the value past which the claw is open</source>
        <translation>el valor a partir del cual la garra está abierta</translation>
    </message>
    <message>
        <location line="+2" />
        <source>CLOSE and OPEN are the same value</source>
        <translation>CLOSE y OPEN tienen el mismo valor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>OPEN is nearer the claw's open end than CLOSE</source>
        <translation>OPEN queda más cerca que CLOSE del extremo abierto de la garra</translation>
    </message>
    <message>
        <location line="+7" />
        <source>FINGERS belongs to GRIP and must follow it</source>
        <translation>FINGERS pertenece a GRIP y debe ir después de él</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put it after the GRIP statement</source>
        <translation>póngalo después de la instrucción GRIP</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a body id</source>
        <translation>un id de cuerpo</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+97" />
        <source>the goal's id</source>
        <translation>el id del objetivo</translation>
    </message>
    <message>
        <location line="-94" />
        <source>goal '%1' is defined twice</source>
        <translation>el objetivo '%1' está definido dos veces</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give every goal its own id</source>
        <translation>dé a cada objetivo su propio id</translation>
    </message>
    <message>
        <location line="+5" />
        <source>(GOAL id REACH BODY b POINT x y z AT x y z TOL d)</source>
        <translation>(GOAL id REACH BODY b POINT x y z AT x y z TOL d)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(the point on the body, in its frame)</source>
        <translation>(el punto en el cuerpo, en su sistema de referencia)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(the target in the world)</source>
        <translation>(el destino en el mundo)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the target</source>
        <translation>el destino</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+12" />
        <source>(how near [m])</source>
        <translation>(qué tan cerca [m])</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+12" />
        <source>the tolerance [m]</source>
        <translation>la tolerancia [m]</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+12" />
        <location line="+39" />
        <location line="+1" />
        <source>the tolerance</source>
        <translation>la tolerancia</translation>
    </message>
    <message>
        <location line="-45" />
        <source>(GOAL id PLACE AT x y z TOL d: the load's centre of mass)</source>
        <translation>(GOAL id PLACE AT x y z TOL d: el centro de masa de la carga)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the load's target position</source>
        <translation>la posición de destino de la carga</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the seat zone [m]</source>
        <translation>la zona de asiento [m]</translation>
    </message>
    <message>
        <location line="+4" />
        <source>expected the kind of goal: REACH, JOINT, GRASP or PLACE</source>
        <translation>se esperaba el tipo de objetivo: REACH, JOINT, GRASP o PLACE</translation>
    </message>
    <message>
        <location line="+1" />
        <source>e.g. GOAL g1 REACH BODY 6 POINT 0 0 0 AT 1 2 0.5 TOL 0.1</source>
        <translation>p. ej. GOAL g1 REACH BODY 6 POINT 0 0 0 AT 1 2 0.5 TOL 0.1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the direction on the body</source>
        <translation>la dirección en el cuerpo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(ALIGN x y z WITH x y z ANGTOL a)</source>
        <translation>(ALIGN x y z WITH x y z ANGTOL a)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the direction in the world</source>
        <translation>la dirección en el mundo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(the angle tolerance)</source>
        <translation>(la tolerancia angular)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+1" />
        <source>the angle tolerance</source>
        <translation>la tolerancia angular</translation>
    </message>
    <message>
        <location line="+2" />
        <source>ALIGN applies to REACH and PLACE goals</source>
        <translation>ALIGN se aplica a los objetivos REACH y PLACE</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove it</source>
        <translation>elimínelo</translation>
    </message>
    <message>
        <location line="+9" />
        <source>(JOINT id AT value TOL d)</source>
        <translation>(JOINT id AT valor TOL d)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the joint's target</source>
        <translation>el valor objetivo de la articulación</translation>
    </message>
    <message>
        <location line="+6" />
        <source>JOINT lines belong to a JOINT goal</source>
        <translation>las líneas JOINT pertenecen a un objetivo JOINT</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write GOAL id JOINT, then the JOINT lines</source>
        <translation>escriba GOAL id JOINT y luego las líneas JOINT</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the dwell time [s]</source>
        <translation>el tiempo de permanencia [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the dwell time</source>
        <translation>el tiempo de permanencia</translation>
    </message>
    <message>
        <location line="+11" />
        <source>NAME belongs to a GOAL, a WORKER or a PART and must follow it</source>
        <translation>NAME pertenece a un GOAL, un WORKER o un PART y debe ir después de él</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put it on the line after its GOAL, WORKER or PART</source>
        <translation>póngalo en la línea que sigue a su GOAL, WORKER o PART</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the time on the goal before the hint shows [s]</source>
        <translation>el tiempo en el objetivo antes de que aparezca la pista [s]</translation>
    </message>
    <message>
        <location line="+8" />
        <source>(WORKER G id id … ZONE d PENALTY p: the scene's graphics of the person)</source>
        <translation>(WORKER G id id … ZONE d PENALTY p: los gráficos de la persona en la escena)</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+20" />
        <source>a graphic id</source>
        <translation>un id de gráfico</translation>
    </message>
    <message>
        <location line="-18" />
        <source>WORKER lists no graphic</source>
        <translation>WORKER no enumera ningún gráfico</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give the scene's G ids of the person</source>
        <translation>indique los id G de la persona en la escena</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the safety zone [m]</source>
        <translation>la zona de seguridad [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the safety zone</source>
        <translation>la zona de seguridad</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the penalty [points]</source>
        <translation>la penalización [puntos]</translation>
    </message>
    <message>
        <location line="+8" />
        <source>(PART [SCENE|MODEL] G id id …, then a NAME line)</source>
        <translation>(PART [SCENE|MODEL] G id id …, y luego una línea NAME)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>PART lists no graphic</source>
        <translation>PART no enumera ningún gráfico</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give the G ids of the part</source>
        <translation>indique los id G de la pieza</translation>
    </message>
    <message>
        <location line="+6" />
        <source>(AVOID SCENE PENALTY p NEAR d HARD v)</source>
        <translation>(AVOID SCENE PENALTY p NEAR d HARD v)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the penalty per hit [points]</source>
        <translation>la penalización por golpe [puntos]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the near-miss distance [m]</source>
        <translation>la distancia de casi choque [m]</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the speed of a hard hit [m/s]</source>
        <translation>la velocidad de un golpe fuerte [m/s]</translation>
    </message>
    <message>
        <location line="+5" />
        <source>(OVERLOAD PENALTY p)</source>
        <translation>(OVERLOAD PENALTY p)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the penalty per overload [points]</source>
        <translation>la penalización por sobrecarga [puntos]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>(LIMITS PENALTY p SPEED f)</source>
        <translation>(LIMITS PENALTY p SPEED f)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the penalty per limit bang [points]</source>
        <translation>la penalización por golpe contra un tope [puntos]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the fraction of the drive's speed</source>
        <translation>la fracción de la velocidad del accionamiento</translation>
    </message>
    <message>
        <location line="+5" />
        <source>(DROP PENALTY p)</source>
        <translation>(DROP PENALTY p)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the penalty for releasing the load out of place [points]</source>
        <translation>la penalización por soltar la carga fuera de lugar [puntos]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>unknown statement '%1'</source>
        <translation>instrucción desconocida '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a tutorial's statements are TUTORIAL, TITLE, INTRO, MODEL, SCENE, PROFILE, DEMO, DRIVES, SET, TIME, PASS, WEIGHTS, JERK, TRACK, GRIP, CLAW, FINGERS, GOAL (with ALIGN, JOINT, DWELL, NAME), HINT, WORKER, PART, AVOID, OVERLOAD, LIMITS, DROP</source>
        <translation>las instrucciones de un tutorial son TUTORIAL, TITLE, INTRO, MODEL, SCENE, PROFILE, DEMO, DRIVES, SET, TIME, PASS, WEIGHTS, JERK, TRACK, GRIP, CLAW, FINGERS, GOAL (con ALIGN, JOINT, DWELL, NAME), HINT, WORKER, PART, AVOID, OVERLOAD, LIMITS, DROP</translation>
    </message>
    <message>
        <location line="+13" />
        <source>the file has no TUTORIAL statement</source>
        <translation>el archivo no tiene instrucción TUTORIAL</translation>
    </message>
    <message>
        <location line="+1" />
        <source>start the file with TUTORIAL &lt;id&gt;, e.g. TUTORIAL T0</source>
        <translation>comience el archivo con TUTORIAL &lt;id&gt;, p. ej. TUTORIAL T0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the tutorial names no MODEL</source>
        <translation>el tutorial no nombra ningún MODEL</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add MODEL "path/to/model.pad"</source>
        <translation>agregue MODEL "ruta/al/modelo.pad"</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the tutorial has no GOAL</source>
        <translation>el tutorial no tiene GOAL</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add at least one GOAL</source>
        <translation>agregue al menos un GOAL</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the weights add up to %1, not 100</source>
        <translation>los pesos suman %1, no 100</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the score is out of 100: make TIME + PATH + SMOOTH + SAFETY = 100</source>
        <translation>el puntaje es sobre 100: haga que TIME + PATH + SMOOTH + SAFETY = 100</translation>
    </message>
    <message>
        <location filename="../ide/cli/tutorial.cpp" line="+246" />
        <source>an autopilot path</source>
        <translation>un recorrido de piloto automático</translation>
    </message>
    <message>
        <location line="+1" />
        <source>an autopilot path is a short text file of waypoints; check that this is one</source>
        <translation>un recorrido de piloto automático es un archivo de texto corto con puntos de paso; compruebe que este lo es</translation>
    </message>
    <message>
        <location filename="../trainer/input/input_log.cpp" line="+62" />
        <source>an input log</source>
        <translation>un registro de entradas</translation>
    </message>
    <message>
        <location line="+1" />
        <source>an input log is a text file that padrob writes while a run is recorded; check that this is one</source>
        <translation>un registro de entradas es un archivo de texto que padrob escribe mientras graba una ejecución; compruebe que este lo es</translation>
    </message>
    <message>
        <location filename="../trainer/station/profile_store.cpp" line="+29" />
        <source>a station profile</source>
        <translation>un perfil de puesto</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a station profile is a short JSON file; check that this is one</source>
        <translation>un perfil de puesto es un archivo JSON corto; compruebe que este lo es</translation>
    </message>
    <message>
        <location filename="../trainer/training/attempt_log.cpp" line="-54" />
        <source>a pending attempt</source>
        <translation>un intento pendiente</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a pending attempt is a JSON file that padrob writes; check that this is one</source>
        <translation>un intento pendiente es un archivo JSON que padrob escribe; compruebe que este lo es</translation>
    </message>
    <message>
        <location filename="../trainer/training/camera_path.cpp" line="-36" />
        <source>a camera path</source>
        <translation>un recorrido de cámara</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a camera path is a text file that padrob writes while a demonstration is recorded; check that this is one</source>
        <translation>un recorrido de cámara es un archivo de texto que padrob escribe mientras graba una demostración; compruebe que este lo es</translation>
    </message>
</context>
<context>
    <name>padrob</name>
    <message>
        <location filename="../ide/cli/bench.cpp" line="+236" />
        <source>the simulation failed: %1</source>
        <translation>la simulación falló: %1</translation>
    </message>
    <message>
        <location line="+144" />
        <source>not compared with --integrator adaptive (MuJoCo is timed with RK4 at dt)</source>
        <translation>sin comparar con --integrator adaptive (a MuJoCo se le mide RK4 con dt)</translation>
    </message>
    <message>
        <location line="+10" />
        <source>no timings</source>
        <translation>sin tiempos medidos</translation>
    </message>
    <message>
        <location line="+61" />
        <source>generated model of %1 bodies does not compile</source>
        <translation>el modelo generado de %1 cuerpos no compila</translation>
    </message>
    <message>
        <location line="+13" />
        <source>tree of %1 bodies: %2</source>
        <translation>árbol de %1 cuerpos: %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source>chain of %1 bodies: %2</source>
        <translation>cadena de %1 cuerpos: %2</translation>
    </message>
    <message>
        <location line="+174" />
        <source>machine: %1, %2 cores</source>
        <translation>máquina: %1, %2 núcleos</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>each figure: the median of %n run(s) after a warm-up run, and the fastest – slowest run</source>
        <translation>
            <numerusform>cada cifra: la mediana de %n ejecución tras una de calentamiento, y la más rápida – la más lenta</numerusform>
            <numerusform>cada cifra: la mediana de %n ejecuciones tras una de calentamiento, y la más rápida – la más lenta</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6" />
        <source>model: %1 (bodies: %2, drives: %3, loop closures: %4)</source>
        <translation>modelo: %1 (cuerpos: %2, accionamientos: %3, cierres de lazo: %4)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>scene: %1; CONTACT added (the model has none): MU 0.5, E 0</source>
        <translation>escena: %1; CONTACT agregado (el modelo no lo tiene): MU 0.5, E 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>scene: %1; the model's CONTACT</source>
        <translation>escena: %1; el CONTACT del modelo</translation>
    </message>
    <message>
        <location line="+4" />
        <source>steps: %1 of dt = %2 ms, %3</source>
        <translation>pasos: %1 de dt = %2 ms, %3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>adaptive integrator (Dormand–Prince 5(4), rtol 1e-8)</source>
        <translation>integrador adaptativo (Dormand–Prince 5(4), rtol 1e-8)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>RK4</source>
        <translation>RK4</translation>
    </message>
    <message>
        <location line="+2" />
        <source>[µs]</source>
        <translation>[µs]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>median</source>
        <translation>mediana</translation>
    </message>
    <message>
        <location line="+1" />
        <source>min – max</source>
        <translation>mín – máx</translation>
    </message>
    <message>
        <location line="+1" />
        <source>forward dynamics, per evaluation</source>
        <translation>dinámica directa, por evaluación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 evaluations/s</source>
        <translation>%1 evaluaciones/s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>realtime factor %1 (%2 – %3)</source>
        <translation>factor de tiempo real %1 (%2 – %3)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>adaptive, per simulated ms</source>
        <translation>adaptativo, por ms simulado</translation>
    </message>
    <message>
        <location line="+2" />
        <source>RK4 step</source>
        <translation>paso de RK4</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 steps/s, %2</source>
        <translation>%1 pasos/s, %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RK4 step, commands held</source>
        <translation>paso de RK4, comandos mantenidos</translation>
    </message>
    <message>
        <location line="+0" />
        <source>no restart after a new command</source>
        <translation>sin reinicio tras un comando nuevo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RK4 step, passive, no limits</source>
        <translation>paso de RK4, pasivo, sin límites</translation>
    </message>
    <message>
        <location line="+0" />
        <source>no drives, no events</source>
        <translation>sin accionamientos, sin eventos</translation>
    </message>
    <message>
        <location line="+3" />
        <source>contact phase, per RK4 step</source>
        <translation>fase de contacto, por paso de RK4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 contact points at a step's end (mean)</source>
        <translation>%1 puntos de contacto al final de un paso (media)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>reference N–E system, per solve</source>
        <translation>N–E de referencia, por resolución</translation>
    </message>
    <message>
        <location line="+1" />
        <source>×%1 Padrob's forward dynamics</source>
        <translation>×%1 la dinámica directa de Padrob</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reference RK4 step</source>
        <translation>paso de RK4 de referencia</translation>
    </message>
    <message>
        <location line="+2" />
        <source>×%1 Padrob's RK4 step</source>
        <translation>×%1 el paso de RK4 de Padrob</translation>
    </message>
    <message>
        <location line="+3" />
        <source>MuJoCo RK4 step (passive, no limits)</source>
        <translation>MuJoCo: paso RK4 pasivo, sin límites</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob / MuJoCo %1 (passive %2)</source>
        <translation>Padrob / MuJoCo %1 (pasivo %2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MuJoCo forward (mj_forward)</source>
        <translation>MuJoCo directa (mj_forward)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob / MuJoCo %1</source>
        <translation>Padrob / MuJoCo %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MuJoCo RK4 step, geoms and contacts</source>
        <translation>paso de RK4 de MuJoCo, geoms y contactos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob / MuJoCo %1 (%2 geoms, %3 contacts)</source>
        <translation>Padrob / MuJoCo %1 (%2 geoms, %3 contactos)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Steps: every drive commanded by a sine (amplitude 0.8, 0.5 Hz, phases spread) set before every
step (held: set once), limits and relief valves watched as events, the joint reactions computed
at every step's end. Events in one run: %1.</source>
        <translation>Pasos: cada accionamiento comandado por una sinusoide (amplitud 0.8, 0.5 Hz, fases repartidas)
fijada antes de cada paso (mantenidos: fijada una vez), límites y válvulas de alivio vigilados
como eventos, las reacciones en las articulaciones calculadas al final de cada paso. Eventos
en una ejecución: %1.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Reference: the thesis's Newton–Euler system A·X = B (eq. 2.8–2.11), dense LU, %1 solves
and %2 RK4 steps per run, modes and commands held, no events; its θ̈ differs from Padrob's
by %3 (relative).</source>
        <translation>Referencia: el sistema de Newton–Euler de la tesis A·X = B (ec. 2.8–2.11), LU densa, %1
resoluciones y %2 pasos de RK4 por ejecución, modos y comandos mantenidos, sin eventos; su θ̈
difiere del de Padrob en %3 (relativo).</translation>
    </message>
    <message>
        <location line="+9" />
        <source>MuJoCo: the same trajectory within %1 m over %2 s.</source>
        <translation>MuJoCo: la misma trayectoria, a menos de %1 m, durante %2 s.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MuJoCo: the same trajectory within %1 m over %2 s; adjusted for MuJoCo:</source>
        <translation>MuJoCo: la misma trayectoria, a menos de %1 m, durante %2 s; ajustado para MuJoCo:</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Allocations in the step loop: not counted here (tests/alloc counts them).</source>
        <translation>Asignaciones de memoria en el ciclo de pasos: no se cuentan aquí (las cuenta tests/alloc).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>scaling: µs per RK4 step (median) of generated models: drives on every 3rd joint,
limits on all; commands held, or set every step</source>
        <translation>escalamiento: µs por paso de RK4 (mediana) de modelos generados: accionamientos en una de cada
3 articulaciones, límites en todas; comandos mantenidos, o fijados en cada paso</translation>
    </message>
    <message>
        <location line="+4" />
        <source>bodies</source>
        <translation>cuerpos</translation>
    </message>
    <message>
        <location line="+0" />
        <source>chain, held</source>
        <translation>cadena, mant.</translation>
    </message>
    <message>
        <location line="+0" />
        <source>chain, commanded</source>
        <translation>cadena, comand.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>tree, held</source>
        <translation>árbol, mant.</translation>
    </message>
    <message>
        <location line="+0" />
        <source>tree, commanded</source>
        <translation>árbol, comand.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>  p: time ∝ n^p by least squares on log–log (p ≈ 1 is linear)</source>
        <translation>  p: tiempo ∝ n^p por mínimos cuadrados en log–log (p ≈ 1 es lineal)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Usage: padrob bench MODEL [--scene FILE] [OPTIONS]
       padrob bench --scaling [OPTIONS]

Times the solver on a model: forward dynamics, RK4 steps with drives, limits and
joint reactions, the real-time factor, and the thesis's reference Newton–Euler
system A·X = B; with MuJoCo built in, MuJoCo on the same tree side by side.
Each figure is the median of R runs after one warm-up run, with the fastest and
slowest run (the machine is noisy); times in µs per evaluation or per step.

  --steps N             steps per timed run (default 5000); the forward dynamics
                        are timed over N evaluations, the reference over
                        min(N, 1000) solves and min(N, 250) steps
  --runs R              timed runs per figure (default 5)
  --dt H                step [s] (default 0.001)
  --integrator M        rk4 (default) or adaptive (Dormand–Prince 5(4), rtol 1e-8:
                        time per simulated millisecond)
  --json                print one JSON object (format "padrob-bench", version 1)
  --scaling             also time generated chains and binary trees of 10, 30, 100,
                        300 and 1000 bodies and fit time ∝ n^p (MODEL may then be
                        left out)
  --no-mujoco           skip the comparison with MuJoCo
  --scene FILE          run the model in a scene (its ground graphics) with contacts:
                        the model's CONTACT, or CONTACT (MU 0.5, E 0) added when it
                        has none; also times the contact phase per step (contact_us)
                        and MuJoCo on the export with the geoms (ratio_vs_mujoco)

The RK4 steps command every drive with a slow sine, set before every step (so
valves open and close and every step restarts the integrator, as at the station),
watch limits and relief valves, and compute the joint reactions at every
step's end; they are also timed with the commands held, and passive without
limits. The real-time factor is dt / step time.

Exit status: 0 success; 1 the model has errors or a simulation failed;
2 usage error or unreadable model.
</source>
        <translation>Uso: padrob bench MODELO [--scene ARCHIVO] [OPCIONES]
     padrob bench --scaling [OPCIONES]

Mide los tiempos del cálculo en un modelo: dinámica directa, pasos de RK4 con
accionamientos, límites y reacciones en las articulaciones, el factor de tiempo
real, y el sistema de Newton–Euler de referencia de la tesis A·X = B; con MuJoCo
incluido, MuJoCo con el mismo árbol, lado a lado.
Cada cifra es la mediana de R ejecuciones tras una de calentamiento, con la más
rápida y la más lenta (la máquina tiene ruido); tiempos en µs por evaluación o por
paso.

  --steps N             pasos por ejecución medida (por omisión 5000); la dinámica
                        directa se mide sobre N evaluaciones, la referencia sobre
                        min(N, 1000) resoluciones y min(N, 250) pasos
  --runs R              ejecuciones medidas por cifra (por omisión 5)
  --dt H                paso [s] (por omisión 0.001)
  --integrator M        rk4 (por omisión) o adaptive (Dormand–Prince 5(4), rtol 1e-8:
                        tiempo por milisegundo simulado)
  --json                escribe un objeto JSON (formato "padrob-bench", versión 1)
  --scaling             mide además cadenas y árboles binarios generados de 10, 30,
                        100, 300 y 1000 cuerpos y ajusta tiempo ∝ n^p (MODELO se puede
                        omitir entonces)
  --no-mujoco           omite la comparación con MuJoCo
  --scene ARCHIVO       ejecuta el modelo en una escena (sus gráficos del suelo) con
                        contactos: el CONTACT del modelo, o CONTACT (MU 0.5, E 0)
                        agregado si no lo tiene; mide además la fase de contacto por
                        paso (contact_us) y MuJoCo en la exportación con los geoms
                        (ratio_vs_mujoco)

Los pasos de RK4 comandan cada accionamiento con una sinusoide lenta, fijada antes
de cada paso (así las válvulas abren y cierran y cada paso reinicia el integrador,
como en el puesto), vigilan límites y válvulas de alivio, y calculan las reacciones
en las articulaciones al final de cada paso; también se miden con los comandos
mantenidos, y pasivos sin límites. El factor de tiempo real es dt / tiempo del paso.

Estado de salida: 0 éxito; 1 el modelo tiene errores o una simulación falló;
2 error de uso o modelo ilegible.
</translation>
    </message>
    <message>
        <location line="+49" />
        <location line="+5" />
        <location filename="../ide/cli/centre.cpp" line="+90" />
        <location line="+6" />
        <location line="+2" />
        <location line="+3" />
        <location line="+3" />
        <location line="+565" />
        <location line="+51" />
        <location filename="../ide/cli/export.cpp" line="+92" />
        <location filename="../ide/cli/simulate.cpp" line="+243" />
        <location filename="../ide/cli/tutorial.cpp" line="-58" />
        <source>%1 needs a value</source>
        <translation>%1 necesita un valor</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 must be a whole number from 1 to %2, not '%3'</source>
        <translation>%1 debe ser un número entero de 1 a %2, no '%3'</translation>
    </message>
    <message>
        <location line="+7" />
        <source>--dt must be a number of seconds above 0 and at most 1, not '%1'</source>
        <translation>--dt debe ser un número de segundos mayor que 0 y hasta 1, no '%1'</translation>
    </message>
    <message>
        <location line="+6" />
        <location filename="../ide/cli/simulate.cpp" line="+19" />
        <source>--integrator must be rk4 or adaptive, not '%1'</source>
        <translation>--integrator debe ser rk4 o adaptive, no '%1'</translation>
    </message>
    <message>
        <location line="+4" />
        <location filename="../ide/cli/centre.cpp" line="-488" />
        <location line="+275" />
        <location line="+165" />
        <location line="+51" />
        <location line="+51" />
        <location filename="../ide/cli/export.cpp" line="+15" />
        <location filename="../ide/cli/inertia.cpp" line="+196" />
        <location filename="../ide/cli/main.cpp" line="+138" />
        <location line="+26" />
        <location filename="../ide/cli/simulate.cpp" line="+25" />
        <location filename="../ide/cli/tutorial.cpp" line="+8" />
        <source>unknown option '%1'</source>
        <translation>opción desconocida '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <location filename="../ide/cli/export.cpp" line="+1" />
        <location filename="../ide/cli/inertia.cpp" line="+4" />
        <location filename="../ide/cli/main.cpp" line="+4" />
        <location filename="../ide/cli/simulate.cpp" line="+1" />
        <source>give one model</source>
        <translation>indique un solo modelo</translation>
    </message>
    <message>
        <location line="+3" />
        <location filename="../ide/cli/export.cpp" line="+4" />
        <location filename="../ide/cli/inertia.cpp" line="-1" />
        <location filename="../ide/cli/main.cpp" line="-27" />
        <location line="+26" />
        <location filename="../ide/cli/simulate.cpp" line="+3" />
        <source>no model given</source>
        <translation>no se indicó ningún modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--scene needs a model</source>
        <translation>--scene necesita un modelo</translation>
    </message>
    <message>
        <location line="+27" />
        <source>%1: the model has no moving body: nothing to time</source>
        <translation>%1: el modelo no tiene ningún cuerpo móvil: no hay nada que medir</translation>
    </message>
    <message>
        <location line="+17" />
        <source>MuJoCo: %1</source>
        <translation>MuJoCo: %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>scaling: %1</source>
        <translation>escalamiento: %1</translation>
    </message>
    <message>
        <location filename="../ide/cli/cli_io.cpp" line="+26" />
        <source>Try 'padrob %1 --help'.</source>
        <translation>Pruebe 'padrob %1 --help'.</translation>
    </message>
    <message>
        <location line="+92" />
        <source>the values given on the command line do not fit the model:</source>
        <translation>los valores dados en la línea de comandos no calzan con el modelo:</translation>
    </message>
    <message>
        <location filename="../ide/cli/export.cpp" line="-65" />
        <source>Usage: padrob export --mjcf MODEL [--scene FILE] [--out FILE] [--dt H] [--check]

Writes a model without closed loops as MuJoCo's MJCF (XML). The bodies are posed
with every joint at 0, so MuJoCo's qpos of each joint is Padrob's coordinate
(the angle for T 0 and T 1 joints: a T 1 joint's length is not a coordinate in
MuJoCo; the displacement for T 2); the keyframe "initial" holds the model's
initial state. MuJoCo gets a passive model: drives, relief valves, limit
impulses and applied forces are not exported (the file's header says so). With
CONTACT the graphics become geoms (a TUBE a ring of boxes; CONE, PRISM and MESH
their convex hulls; NOCONTACT ones visual only) and contacts are on, with MuJoCo's
law set to approximate Padrob's; without CONTACT there are no geoms and contacts
are off. Bodies MuJoCo would refuse (massless, or an inertia breaking I1 + I2 &gt;= I3)
get the nearest values it accepts, with the true ones in a comment there.

  --mjcf        the format (required; the only one)
  --out FILE    write the MJCF there (default: standard output); the file is
                replaced whole or not at all
  --dt H        the time step written in &lt;option&gt; [s] (default 0.001)
  --scene FILE  with CONTACT: the scene's ground graphics (e.g. a mill) as world
                geoms, and the solids overlapping them at the start excluded
  --check       load the MJCF into MuJoCo (when padrob was built with it), put
                the true masses and inertias in, and check that MuJoCo and Padrob
                follow the same trajectory for 0.2 s (RK4 at --dt, every joint
                passive, no limits, the centres of mass within 1e-6 m); the
                result goes to standard error

Exit status: 0 success; 1 the model has errors, has closed loops, or MuJoCo
disagrees (--check); 2 usage error, unreadable model, or --check in a padrob
built without MuJoCo. On failure nothing is written.
</source>
        <translation>Uso: padrob export --mjcf MODELO [--scene ARCHIVO] [--out ARCHIVO] [--dt H] [--check]

Escribe un modelo sin lazos cerrados en el formato MJCF (XML) de MuJoCo. Los cuerpos
se ubican con todas las articulaciones en 0, así que el qpos de cada articulación en
MuJoCo es la coordenada de Padrob (el ángulo en las articulaciones T 0 y T 1: el
largo de una articulación T 1 no es una coordenada en MuJoCo; el desplazamiento en
T 2); el keyframe "initial" guarda el estado inicial del modelo. MuJoCo recibe un
modelo pasivo: accionamientos, válvulas de alivio, impulsos en los límites y fuerzas
aplicadas no se exportan (lo dice el encabezado del archivo). Con CONTACT los
gráficos se vuelven geoms (un TUBE, un anillo de cajas; CONE, PRISM y MESH, sus
envolventes convexas; los NOCONTACT, solo visuales) y los contactos quedan activos,
con la ley de MuJoCo ajustada para aproximar la de Padrob; sin CONTACT no hay geoms
y los contactos quedan desactivados. Los cuerpos
que MuJoCo rechazaría (sin masa, o con una inercia que no cumple I1 + I2 &gt;= I3)
reciben los valores aceptables más cercanos, con los verdaderos en un comentario.

  --mjcf        el formato (obligatorio; el único)
  --out ARCHIVO escribe el MJCF ahí (por omisión: la salida estándar); el archivo
                se reemplaza entero o no se toca
  --dt H        el paso de tiempo escrito en &lt;option&gt; [s] (por omisión 0.001)
  --scene ARCHIVO  con CONTACT: los gráficos del suelo de la escena (p. ej. un
                molino) como geoms del mundo, y excluidos los sólidos que al inicio
                se traslapan con ellos
  --check       carga el MJCF en MuJoCo (si padrob se compiló con él), le pone las
                masas e inercias verdaderas, y comprueba que MuJoCo y Padrob siguen
                la misma trayectoria durante 0.2 s (RK4 con --dt, todas las
                articulaciones pasivas, sin límites, los centros de masa a menos de
                1e-6 m); el resultado va a la salida de errores

Estado de salida: 0 éxito; 1 el modelo tiene errores, tiene lazos cerrados, o MuJoCo
no coincide (--check); 2 error de uso, modelo ilegible, o --check en un padrob
compilado sin MuJoCo. Si falla, no se escribe nada.
</translation>
    </message>
    <message>
        <location line="+48" />
        <source>--scene needs a file name</source>
        <translation>--scene necesita un nombre de archivo</translation>
    </message>
    <message>
        <location line="+3" />
        <source>--out needs a file name</source>
        <translation>--out necesita un nombre de archivo</translation>
    </message>
    <message>
        <location line="+4" />
        <location filename="../ide/cli/simulate.cpp" line="-42" />
        <source>--dt must be a positive number of seconds, not '%1'</source>
        <translation>--dt debe ser un número positivo de segundos, no '%1'</translation>
    </message>
    <message>
        <location line="+9" />
        <source>give the format: --mjcf (the only one)</source>
        <translation>indique el formato: --mjcf (el único)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>--check needs MuJoCo, and this padrob was built without it</source>
        <translation>--check necesita MuJoCo, y este padrob se compiló sin él</translation>
    </message>
    <message>
        <location line="+21" />
        <location line="+25" />
        <location line="+13" />
        <source>note: %1</source>
        <translation>nota: %1</translation>
    </message>
    <message>
        <location line="-38" />
        <source>the model has no CONTACT: no geoms, and the scene is not exported</source>
        <translation>el modelo no tiene CONTACT: no hay geoms, y la escena no se exporta</translation>
    </message>
    <message>
        <location line="+26" />
        <source>set in MuJoCo after loading: %1</source>
        <translation>fijado en MuJoCo después de cargar: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MuJoCo agrees with Padrob over %1 s (RK4, dt %2 s): the centres of mass are at most %3 m apart</source>
        <translation>MuJoCo coincide con Padrob durante %1 s (RK4, dt %2 s): los centros de masa están a lo más a %3 m</translation>
    </message>
    <message>
        <location line="+5" />
        <source>MuJoCo loads the export with its %1 geoms and contacts on</source>
        <translation>MuJoCo carga la exportación con sus %1 geoms y los contactos activos</translation>
    </message>
    <message>
        <location line="+2" />
        <source>with contacts over %1 s (every joint passive, no limits): the centres of mass are at most %2 m apart; at the end:</source>
        <translation>con contactos durante %1 s (todas las articulaciones pasivas, sin límites): los centros de masa distan a lo más %2 m; al final:</translation>
    </message>
    <message>
        <location line="+7" />
        <source>  body %1: Padrob %2, MuJoCo %3</source>
        <translation>  cuerpo %1: Padrob %2, MuJoCo %3</translation>
    </message>
    <message>
        <location line="+8" />
        <source>cannot write to standard output</source>
        <translation>no se puede escribir en la salida estándar</translation>
    </message>
    <message>
        <location filename="../ide/cli/inertia.cpp" line="-160" />
        <source>n/a (file: 0)</source>
        <translation>n/a (archivo: 0)</translation>
    </message>
    <message>
        <location line="+117" />
        <source>Usage: padrob inertia MODEL [--body I] [--write]

Computes each body's mass, centre of mass and inertia tensor (about the centre of
mass, in body axes) from its solids: the graphics (G) with MASS or RHO, combined
with the parallel-axis theorem. For each such body it prints the computed B line
beside the one in the file, the relative difference of the mass and of each
moment, and the principal moments.

  --body I   only body I
  --write    replace each computed body's B line in the file (its NAME and any
             comment are kept, every other line byte for byte), after copying
             the file to MODEL.bak

A model with errors (or a mesh that cannot be used) is not computed and not
written: its problems are printed as by 'padrob check' and the exit status is 1.
Exit status 2 on a usage error or a file that cannot be read or written.
</source>
        <translation>Uso: padrob inertia MODELO [--body I] [--write]

Calcula la masa, el centro de masa y el tensor de inercia (respecto del centro de
masa, en los ejes del cuerpo) de cada cuerpo a partir de sus sólidos: los gráficos
(G) con MASS o RHO, combinados con el teorema de ejes paralelos. Para cada uno de
esos cuerpos muestra la línea B calculada junto a la del archivo, la diferencia
relativa de la masa y de cada momento, y los momentos principales.

  --body I   solo el cuerpo I
  --write    reemplaza en el archivo la línea B de cada cuerpo calculado (se
             conservan su NAME y cualquier comentario, y todas las demás líneas byte
             a byte), después de copiar el archivo a MODELO.bak

Un modelo con errores (o una malla que no se puede usar) no se calcula ni se
escribe: sus problemas se informan como con 'padrob check' y el estado de salida
es 1. Estado de salida 2 ante un error de uso o un archivo que no se puede leer o
escribir.
</translation>
    </message>
    <message>
        <location line="+31" />
        <source>--body needs a body id</source>
        <translation>--body necesita un id de cuerpo</translation>
    </message>
    <message>
        <location line="+5" />
        <source>--body takes a body id (a positive integer), not '%1'</source>
        <translation>--body recibe un id de cuerpo (un entero positivo), no '%1'</translation>
    </message>
    <message>
        <location line="+21" />
        <source>--body: the model has no body %1</source>
        <translation>--body: el modelo no tiene el cuerpo %1</translation>
    </message>
    <message>
        <location line="+19" />
        <source>body %1 has no solids (graphics with MASS or RHO)</source>
        <translation>el cuerpo %1 no tiene sólidos (gráficos con MASS o RHO)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>No body has solids (graphics with MASS or RHO): nothing to compute.</source>
        <translation>Ningún cuerpo tiene sólidos (gráficos con MASS o RHO): no hay nada que calcular.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>cannot read '%1'</source>
        <translation>no se puede leer '%1'</translation>
    </message>
    <message>
        <location line="+13" />
        <source>file:</source>
        <translation>archivo:</translation>
    </message>
    <message>
        <location line="+0" />
        <source>computed:</source>
        <translation>calculado:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>difference:</source>
        <translation>diferencia:</translation>
    </message>
    <message>
        <location line="+0" />
        <source>principal:</source>
        <translation>principales:</translation>
    </message>
    <message>
        <location line="+17" />
        <source>body %1</source>
        <translation>cuerpo %1</translation>
    </message>
    <message>
        <location line="+20" />
        <source>cannot find body %1's B statement in the file; nothing written</source>
        <translation>no se encuentra la sentencia B del cuerpo %1 en el archivo; no se escribió nada</translation>
    </message>
    <message>
        <location line="+16" />
        <source>the updated model would not load as computed; nothing written</source>
        <translation>el modelo actualizado no se cargaría tal como se calculó; no se escribió nada</translation>
    </message>
    <message>
        <location line="+8" />
        <source>cannot write the backup '%1'; nothing written</source>
        <translation>no se puede escribir el respaldo '%1'; no se escribió nada</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot write '%1'</source>
        <translation>no se puede escribir '%1'</translation>
    </message>
    <message numerus="yes">
        <location line="+4" />
        <source>Wrote %n B line(s) to %1 (the old file is %2)</source>
        <translation>
            <numerusform>Se escribió %n línea B en %1 (el archivo anterior es %2)</numerusform>
            <numerusform>Se escribieron %n líneas B en %1 (el archivo anterior es %2)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ide/cli/info_report.cpp" line="+55" />
        <source>dependent</source>
        <comment>role of a joint's coordinate</comment>
        <translation>dependiente</translation>
    </message>
    <message>
        <location line="+1" />
        <source>loop-closure</source>
        <comment>role of a joint</comment>
        <translation>cierre de lazo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>independent</source>
        <comment>role of a joint's coordinate</comment>
        <translation>independiente</translation>
    </message>
    <message>
        <location line="+7" />
        <source>revolute</source>
        <comment>joint type (T 0)</comment>
        <translation>rotacional</translation>
    </message>
    <message>
        <location line="+1" />
        <source>actuator</source>
        <comment>joint type (T 1)</comment>
        <translation>actuador</translation>
    </message>
    <message>
        <location line="+1" />
        <source>prismatic</source>
        <comment>joint type (T 2)</comment>
        <translation>prismática</translation>
    </message>
    <message>
        <location line="+1" />
        <source>free</source>
        <comment>joint type (T 3)</comment>
        <translation>libre</translation>
    </message>
    <message>
        <location line="+21" />
        <location line="+53" />
        <location line="+40" />
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <location line="-68" />
        <source>Model: %1</source>
        <translation>Modelo: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gravity: %1 m/s²</source>
        <translation>Gravedad: %1 m/s²</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Bodies (%1 + ground), total mass %2 kg</source>
        <translation>Cuerpos (%1 + suelo), masa total %2 kg</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+11" />
        <source>name</source>
        <translation>nombre</translation>
    </message>
    <message>
        <location line="-10" />
        <source>mass [kg]</source>
        <translation>masa [kg]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ixx Iyy Izz [kg m²]</source>
        <translation>Ixx Iyy Izz [kg m²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>centre of mass</source>
        <translation>centro de masa</translation>
    </message>
    <message>
        <location line="+3" />
        <source>massless</source>
        <translation>sin masa</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Joints (%1)</source>
        <translation>Articulaciones (%1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>type</source>
        <translation>tipo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>limits</source>
        <translation>límites</translation>
    </message>
    <message>
        <location line="+1" />
        <source>initial</source>
        <translation>inicial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>role</source>
        <translation>rol</translation>
    </message>
    <message>
        <location line="+1" />
        <source>drive</source>
        <translation>accionamiento</translation>
    </message>
    <message>
        <location line="+10" />
        <source>passive</source>
        <translation>pasiva</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Spanning tree (parent body &lt;- joint &lt;- body):</source>
        <translation>Árbol de expansión (cuerpo padre &lt;- articulación &lt;- cuerpo):</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 &lt;- joint %2 &lt;- %3</source>
        <translation>%1 &lt;- articulación %2 &lt;- %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>written from B2 to B1</source>
        <translation>escrita de B2 a B1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Chains:</source>
        <translation>Cadenas:</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: joints %2</source>
        <translation>%1: articulaciones %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Loop-closure joints: %1</source>
        <translation>Articulaciones de cierre de lazo: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Degrees of freedom: %1</source>
        <translation>Grados de libertad: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>independent coordinates (joints): %1</source>
        <translation>coordenadas independientes (articulaciones): %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>dependent coordinates (joints): %1</source>
        <translation>coordenadas dependientes (articulaciones): %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Fluid power: bulk modulus %1 Pa, laminar below %2 Pa</source>
        <translation>Potencia oleohidráulica: módulo de compresibilidad %1 Pa, laminar bajo %2 Pa</translation>
    </message>
    <message>
        <location line="+8" />
        <source>pump %1 %2: %3 L/min, %4 MPa, load-sensing (margin %5 MPa); drives %6</source>
        <translation>bomba %1 %2: %3 L/min, %4 MPa, con detección de carga (margen %5 MPa); accionamientos %6</translation>
    </message>
    <message>
        <location line="+1" />
        <source>pump %1 %2: %3 L/min, %4 MPa, pressure-compensated%5; drives %6</source>
        <translation>bomba %1 %2: %3 L/min, %4 MPa, compensada por presión%5; accionamientos %6</translation>
    </message>
    <message>
        <location filename="../ide/cli/main.cpp" line="-127" />
        <source>Usage: padrob COMMAND [OPTIONS] [ARGS]

Padrob builds real-time training simulators of machines from model files (.pad).

Commands:
  check MODEL...        check models and print their problems
  info MODEL [--json]   describe a model: bodies, joints, chains, degrees of freedom
  simulate MODEL --time T [OPTIONS]
                        simulate a model and write its trajectory as CSV
  inertia MODEL [--body I] [--write]
                        compute bodies' mass and inertia from their solids
  bench MODEL [OPTIONS]  time the solver on a model (and MuJoCo, when built in)
  export --mjcf MODEL [--out FILE]
                        write a tree model as MuJoCo's MJCF
  tutorial FILE [--input LOG | --demo] [--json]
                        check a tutorial, or run it against an input log and score it
  station TUTORIAL... --name NAME
                        a training station without a window on the centre's network
  instructor list|watch|send
                        the training centre's stations: list, watch and command them
  centre key|seal|bench the training centre's key, sealed secrets, scale benchmark

Options:
  -h, --help            show this help (or a command's: padrob COMMAND --help)
  --version             show the version
  --lang es|en          language of the messages, with any command (default: the
                        system's: LANGUAGE, LC_ALL, LC_MESSAGES or LANG)

Exit status: 0 success, 1 the model has errors, 2 usage error or unreadable file.
</source>
        <translation>Uso: padrob COMANDO [OPCIONES] [ARGUMENTOS]

Padrob construye simuladores de entrenamiento en tiempo real de máquinas a partir de
archivos de modelo (.pad).

Comandos:
  check MODELO...       revisa modelos e informa sus problemas
  info MODELO [--json]  describe un modelo: cuerpos, articulaciones, cadenas, grados
                        de libertad
  simulate MODELO --time T [OPCIONES]
                        simula un modelo y escribe su trayectoria en CSV
  inertia MODELO [--body I] [--write]
                        calcula la masa y la inercia de los cuerpos a partir de sus
                        sólidos
  bench MODELO [OPCIONES]
                        mide los tiempos del cálculo en un modelo (y de MuJoCo, si
                        viene incluido)
  export --mjcf MODELO [--out ARCHIVO]
                        escribe un modelo en árbol en el formato MJCF de MuJoCo
  tutorial ARCHIVO [--input REGISTRO | --demo] [--json]
                        revisa un tutorial, o lo ejecuta con un registro de entradas y
                        le asigna puntaje
  station TUTORIAL... --name NOMBRE
                        una estación de entrenamiento sin ventana en la red del centro
  instructor list|watch|send
                        las estaciones del centro de entrenamiento: listarlas,
                        observarlas y darles órdenes
  centre key|seal|bench la clave del centro, secretos sellados, prueba de escala

Opciones:
  -h, --help            muestra esta ayuda (o la de un comando: padrob COMANDO --help)
  --version             muestra la versión
  --lang es|en          idioma de los mensajes, con cualquier comando (por omisión: el
                        del sistema: LANGUAGE, LC_ALL, LC_MESSAGES o LANG)

Estado de salida: 0 éxito, 1 el modelo tiene errores, 2 error de uso o archivo
ilegible.
</translation>
    </message>
    <message>
        <location line="+34" />
        <source>Usage: padrob check MODEL...

Reads each model file and prints every problem found, one per line, as
  file:line:column: error|warning: message [hint]
(the format compilers use, so editors can jump to each problem), then a summary.

Exit status: 0 when no model has errors (warnings are allowed), 1 when some model
has errors, 2 on a usage error or when a file cannot be read.
</source>
        <translation>Uso: padrob check MODELO...

Lee cada archivo de modelo e informa cada problema encontrado, uno por línea, como
  archivo:línea:columna: error|advertencia: mensaje [sugerencia]
(el formato de los compiladores, para que los editores salten a cada problema), y
luego un resumen.

Estado de salida: 0 si ningún modelo tiene errores (se aceptan advertencias), 1 si
algún modelo tiene errores, 2 ante un error de uso o un archivo que no se puede leer.
</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Usage: padrob info MODEL [--json]

Describes a model: its bodies (mass, inertia), joints (type, bodies, limits,
initial value, drive), the spanning tree from ground, the loop-closure joints,
the kinematic chains, the degrees of freedom and which coordinates are
independent or dependent, and the total mass.

  --json   print one JSON object instead (format "padrob-info", version 1;
           documented in docs/cli.md)

A model with errors is not described: its problems are printed as by
'padrob check' and the exit status is 1 (2 if the file cannot be read).
</source>
        <translation>Uso: padrob info MODELO [--json]

Describe un modelo: sus cuerpos (masa, inercia), articulaciones (tipo, cuerpos,
límites, valor inicial, accionamiento), el árbol de expansión desde el suelo, las
articulaciones de cierre de lazo, las cadenas cinemáticas, los grados de libertad,
qué coordenadas son independientes o dependientes, y la masa total.

  --json   escribe en cambio un objeto JSON (formato "padrob-info", versión 1;
           documentado en docs/cli.md)

Un modelo con errores no se describe: sus problemas se informan como con
'padrob check' y el estado de salida es 1 (2 si el archivo no se puede leer).
</translation>
    </message>
    <message numerus="yes">
        <location line="+35" />
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n advertencia</numerusform>
            <numerusform>%n advertencias</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: ok (%2)</source>
        <translation>%1: correcto (%2)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1: ok</source>
        <translation>%1: correcto</translation>
    </message>
    <message numerus="yes">
        <location line="+2" />
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errores</numerusform>
        </translation>
    </message>
    <message>
        <location line="+64" />
        <source>--lang needs a value: es or en</source>
        <translation>--lang necesita un valor: es o en</translation>
    </message>
    <message>
        <location line="+13" />
        <source>--lang must be es or en, not '%1'</source>
        <translation>--lang debe ser es o en, no '%1'</translation>
    </message>
    <message>
        <location line="+26" />
        <location line="+30" />
        <source>Try 'padrob --help'.</source>
        <translation>Pruebe 'padrob --help'.</translation>
    </message>
    <message>
        <location line="-1" />
        <source>unknown command '%1'</source>
        <translation>comando desconocido '%1'</translation>
    </message>
    <message>
        <location filename="../ide/cli/mujoco_bench.cpp" line="+89" />
        <source>MuJoCo's virtual file system refused the MJCF</source>
        <translation>el sistema de archivos virtual de MuJoCo rechazó el MJCF</translation>
    </message>
    <message>
        <location line="+7" />
        <source>MuJoCo refused the exported MJCF: %1</source>
        <translation>MuJoCo rechazó el MJCF exportado: %1</translation>
    </message>
    <message>
        <location line="+77" />
        <source>MuJoCo could not allocate its data</source>
        <translation>MuJoCo no pudo reservar memoria para sus datos</translation>
    </message>
    <message>
        <location line="-58" />
        <source>MuJoCo's model has no body '%1' or joint '%2'</source>
        <translation>el modelo de MuJoCo no tiene el cuerpo '%1' o la articulación '%2'</translation>
    </message>
    <message numerus="yes">
        <location line="+164" />
        <source>every joint passive in both: the model's %n drive(s) are not exported</source>
        <translation>
            <numerusform>todas las articulaciones pasivas en ambos: %n accionamiento del modelo no se exporta</numerusform>
            <numerusform>todas las articulaciones pasivas en ambos: los %n accionamientos del modelo no se exportan</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3" />
        <source>joint limits off in both (%n joint(s) have them)</source>
        <translation>
            <numerusform>límites de las articulaciones desactivados en ambos (%n articulación los tiene)</numerusform>
            <numerusform>límites de las articulaciones desactivados en ambos (%n articulaciones los tienen)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4" />
        <source>Padrob runs without the model's %n applied force(s) (F): they are not exported</source>
        <translation>
            <numerusform>Padrob simula sin %n fuerza aplicada (F) del modelo: no se exporta</numerusform>
            <numerusform>Padrob simula sin las %n fuerzas aplicadas (F) del modelo: no se exportan</numerusform>
        </translation>
    </message>
    <message>
        <location line="-79" />
        <location line="+104" />
        <source>Padrob failed: %1</source>
        <translation>Padrob falló: %1</translation>
    </message>
    <message>
        <location line="-20" />
        <source>the agreement is checked without contacts (MuJoCo's export there has no geoms)</source>
        <translation>la coincidencia se comprueba sin contactos (ahí la exportación a MuJoCo no tiene geoms)</translation>
    </message>
    <message>
        <location line="+34" />
        <source>MuJoCo and Padrob disagree: the centre of mass of body %1 is %2 m apart at t = %3 s (tolerance %4 m; Padrob %5, MuJoCo %6)</source>
        <translation>MuJoCo y Padrob no coinciden: el centro de masa del cuerpo %1 difiere en %2 m en t = %3 s (tolerancia %4 m; Padrob %5, MuJoCo %6)</translation>
    </message>
    <message numerus="yes">
        <location line="+34" />
        <source>MuJoCo warned %n time(s): %1</source>
        <translation>
            <numerusform>MuJoCo advirtió %n vez: %1</numerusform>
            <numerusform>MuJoCo advirtió %n veces: %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ide/cli/simulate.cpp" line="-177" />
        <source>warning: %1</source>
        <translation>advertencia: %1</translation>
    </message>
    <message>
        <location line="+54" />
        <source>--weld takes T:A:B: a time [s] and two body ids, to weld body B to body A (0 = the ground), e.g. 0.5:0:2; not '%1'</source>
        <translation>--weld recibe T:A:B: un instante [s] y dos ids de cuerpo, para soldar el cuerpo B al cuerpo A (0 = el suelo), p. ej. 0.5:0:2; no '%1'</translation>
    </message>
    <message>
        <location line="+2" />
        <source>--release takes T:A:B: a time [s] and two body ids, to release the weld of body B to body A (0 = the ground), e.g. 1.5:0:2; not '%1'</source>
        <translation>--release recibe T:A:B: un instante [s] y dos ids de cuerpo, para liberar la soldadura del cuerpo B al cuerpo A (0 = el suelo), p. ej. 1.5:0:2; no '%1'</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the time must be a finite number of seconds ≥ 0 (from the start), not '%1'</source>
        <translation>el instante debe ser un número finito de segundos ≥ 0 (desde el inicio), no '%1'</translation>
    </message>
    <message>
        <location line="+7" />
        <source>cannot weld a body to itself: give two different bodies A and B</source>
        <translation>no se puede soldar un cuerpo a sí mismo: indique dos cuerpos A y B distintos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot release a body from itself: give the two bodies of a --weld</source>
        <translation>no se puede liberar un cuerpo de sí mismo: indique los dos cuerpos de un --weld</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the ground cannot be welded to a body: put the ground as A, '%1'</source>
        <translation>el suelo no se puede soldar a un cuerpo: ponga el suelo como A, '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the ground is never the welded body B: a weld to the ground is written with the ground as A, '%1'</source>
        <translation>el suelo nunca es el cuerpo soldado B: una soldadura al suelo se escribe con el suelo como A, '%1'</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Usage: padrob simulate MODEL --time T [OPTIONS]

Simulates the model for T seconds and writes its trajectory as CSV.

  --time T              simulated time [s] (required, &gt; 0)
  --dt H                step [s] (default 0.001): the RK4 step, and how often the
                        inputs are read and output rows may be written
  --integrator M        rk4 (fixed step, the real-time integrator; default) or
                        adaptive (error-controlled, for accuracy)
  --rtol R              relative tolerance of the adaptive integrator (default 1e-8)
  --input FILE.csv      operator commands: a column t and one column u&lt;joint id&gt; per
                        drive, values in [-1, 1], held between rows
  --input-log LOG       replay a recorded input log (raw device readings, from
                        padrob-studio's Station workspace) through a station profile,
                        with its timing; instead of --input
  --profile P           the profile for --input-log: a .json file, or the name of one
                        of the model's profiles (default: the one made for the model:
                        keyboard pairs in order, gamepad in banks)
  --set J=VALUE         initial coordinate of joint J (overrides QI; T 1: length)
  --rate J=VALUE        initial rate of joint J (overrides VI)
  --passive             ignore every drive (all joints passive)
  --no-limits           ignore the joint limits LL/UL
  --every N             write one row every N steps (default 1)
  --out FILE.csv        write the CSV there (default: standard output)
  --weld T:A:B          at time T [s] weld body B to body A (0 = the ground) at
                        their relative pose then; repeatable
  --release T:A:B       at time T [s] release the weld of body B to body A;
                        repeatable
  --scene FILE.pad      a scene (ground graphics only, e.g. a mill): under CONTACT
                        the model's solids touch its solids too

Columns: t; q&lt;j&gt; for every joint j in id order (loop-closing joints too;
q&lt;j&gt;x q&lt;j&gt;y q&lt;j&gt;z for a free joint, T 3: its body's translation along B1's
joint axes); qd&lt;j&gt; likewise; ang&lt;j&gt; (the angle, rad) for every
pivoted-actuator (T 1) joint, whose q&lt;j&gt; is the length;
x&lt;i&gt; y&lt;i&gt; z&lt;i&gt;, the world position of the centre of mass of every body i;
F&lt;j&gt;, the force or torque of every drive; pA&lt;j&gt; pB&lt;j&gt;, the chamber pressures
[Pa] of every fluid-power drive (CYL, HMOTOR) in joint id order, then pP&lt;id&gt;,
the supply pressure of every pump; E, the mechanical energy (kinetic +
gravitational) [J]. Events (limits hit and left, relief valves opening and
closing, pumps saturating, cavitation, welds made and released, a closed loop
locking up) are printed on standard error, one per line.

Welds: the simulation stops exactly at each T (between output rows if T is not
a multiple of --dt; the rows stay every --dt), makes or releases the weld and
goes on; a row at T shows the state after it. Several at one T apply in the
order given. B is never the ground (put the ground as A); a body other than
the ground is in one weld at a time, and --release needs that weld in force
at T (else the run fails, exit status 1).

Exit status: 0 success; 1 the model has errors or the simulation failed;
2 usage error or unreadable input. On failure no output file is left behind.
</source>
        <translation>Uso: padrob simulate MODELO --time T [OPCIONES]

Simula el modelo durante T segundos y escribe su trayectoria en CSV.

  --time T              tiempo simulado [s] (obligatorio, &gt; 0)
  --dt H                paso [s] (por omisión 0.001): el paso de RK4, y cada cuánto se
                        leen las entradas y se pueden escribir filas
  --integrator M        rk4 (paso fijo, el integrador de tiempo real; por omisión) o
                        adaptive (con control del error, para mayor exactitud)
  --rtol R              tolerancia relativa del integrador adaptativo (por omisión
                        1e-8)
  --input ARCHIVO.csv   comandos del operador: una columna t y una columna
                        u&lt;id de articulación&gt; por accionamiento, valores en [-1, 1],
                        mantenidos entre filas
  --input-log REGISTRO  reproduce un registro de entradas (lecturas crudas de los
                        dispositivos, del espacio Puesto de padrob-studio) a través de
                        un perfil del puesto, con sus tiempos; en lugar de --input
  --profile P           el perfil para --input-log: un archivo .json, o el nombre de
                        uno de los perfiles del modelo (por omisión: el hecho para el
                        modelo: pares de teclas en orden, gamepad en bancos)
  --set J=VALOR         coordenada inicial de la articulación J (reemplaza QI; T 1:
                        largo)
  --rate J=VALOR        velocidad inicial de la articulación J (reemplaza VI)
  --passive             ignora todos los accionamientos (articulaciones pasivas)
  --no-limits           ignora los límites de las articulaciones LL/UL
  --every N             escribe una fila cada N pasos (por omisión 1)
  --out ARCHIVO.csv     escribe el CSV ahí (por omisión: la salida estándar)
  --weld T:A:B          en el instante T [s] suelda el cuerpo B al cuerpo A (0 = el
                        suelo) en su posición relativa de ese momento; repetible
  --release T:A:B       en el instante T [s] libera la soldadura del cuerpo B al
                        cuerpo A; repetible
  --scene ARCHIVO.pad   una escena (solo gráficos del suelo, p. ej. un molino): con
                        CONTACT los sólidos del modelo también tocan los suyos

Columnas: t; q&lt;j&gt; de cada articulación j por orden de id (también las que cierran
lazos; q&lt;j&gt;x q&lt;j&gt;y q&lt;j&gt;z en una articulación libre, T 3: la traslación de su cuerpo
según los ejes de la articulación en B1); qd&lt;j&gt; igual; ang&lt;j&gt; (el ángulo, rad) de
cada articulación de actuador pivotado (T 1), cuyo q&lt;j&gt; es el largo;
x&lt;i&gt; y&lt;i&gt; z&lt;i&gt;, la posición en el mundo del centro de masa de cada cuerpo i;
F&lt;j&gt;, la fuerza o el torque de cada accionamiento; pA&lt;j&gt; pB&lt;j&gt;, las presiones de
las cámaras [Pa] de cada accionamiento oleohidráulico (CYL, HMOTOR) por orden de
id de articulación, luego pP&lt;id&gt;, la presión de suministro de cada bomba; E, la
energía mecánica (cinética + gravitatoria) [J]. Los eventos (límites alcanzados y
abandonados, válvulas de alivio que abren y cierran, bombas que se saturan,
cavitación, soldaduras hechas y liberadas, un lazo cerrado que se traba) se
informan en la salida de errores, uno por línea.

Soldaduras: la simulación se detiene exactamente en cada T (entre filas si T no es
múltiplo de --dt; las filas siguen cada --dt), hace o libera la soldadura y sigue;
una fila en T muestra el estado posterior. Varias en un mismo T se aplican en el
orden dado. B nunca es el suelo (ponga el suelo como A); un cuerpo distinto del
suelo está en una sola soldadura a la vez, y --release necesita esa soldadura
vigente en T (si no, la ejecución falla, estado de salida 1).

Estado de salida: 0 éxito; 1 el modelo tiene errores o la simulación falló;
2 error de uso o entrada ilegible. Si falla, no queda ningún archivo de salida.
</translation>
    </message>
    <message>
        <location line="+85" />
        <source>--time must be a positive number of seconds, not '%1'</source>
        <translation>--time debe ser un número positivo de segundos, no '%1'</translation>
    </message>
    <message>
        <location line="+7" />
        <source>--rtol must be a number between 0 and 1, not '%1'</source>
        <translation>--rtol debe ser un número entre 0 y 1, no '%1'</translation>
    </message>
    <message>
        <location line="+4" />
        <source>--every must be a whole number ≥ 1, not '%1'</source>
        <translation>--every debe ser un número entero ≥ 1, no '%1'</translation>
    </message>
    <message>
        <location line="+24" />
        <location line="+35" />
        <source>%1 takes J=VALUE (a joint id and a number), not '%2'</source>
        <translation>%1 recibe J=VALOR (un id de articulación y un número), no '%2'</translation>
    </message>
    <message>
        <location line="-24" />
        <source>--time is required</source>
        <translation>--time es obligatorio</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--input and --input-log cannot be combined</source>
        <translation>--input y --input-log no se pueden combinar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--profile goes with --input-log</source>
        <translation>--profile va con --input-log</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--dt is longer than --time</source>
        <translation>--dt es más largo que --time</translation>
    </message>
    <message>
        <location line="+2" />
        <source>--time / --dt is more than 1e9 steps</source>
        <translation>--time / --dt es más de 1e9 pasos</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the time is after the end of the simulation (--time %1 s): give a T between 0 and --time</source>
        <translation>el instante es posterior al final de la simulación (--time %1 s): indique un T entre 0 y --time</translation>
    </message>
    <message>
        <location line="+22" />
        <source>%1: the model has no joint %2</source>
        <translation>%1: el modelo no tiene la articulación %2</translation>
    </message>
    <message>
        <location line="+25" />
        <source>0 (the ground)</source>
        <translation>0 (el suelo)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the model has no body %1; its bodies are %2</source>
        <translation>el modelo no tiene el cuerpo %1; sus cuerpos son %2</translation>
    </message>
    <message>
        <location line="+187" />
        <source>the adaptive integrator failed too: check the model's masses, springs and forces</source>
        <translation>el integrador adaptativo también falló: revise las masas, resortes y fuerzas del modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>run it again with a smaller --dt (now %1 s; e.g. --dt %2) or with --integrator adaptive</source>
        <translation>ejecútelo de nuevo con un --dt menor (ahora %1 s; p. ej. --dt %2) o con --integrator adaptive</translation>
    </message>
    <message>
        <location filename="../ide/cli/tutorial.cpp" line="-170" />
        <source>Usage: padrob tutorial FILE [--input LOG | --demo] [OPTIONS]

Checks a tutorial file (.tut) and, with --input or --demo, runs it without a window:
the input log is replayed through the station profile into the simulation while the
tutorial's checker watches the goals, the grasp, collisions, overloads and time, and
scores the run. Prints whether it passed, the score breakdown and the events with
their times.

  --input LOG           replay this input log (raw device readings, as padrob-studio's
                        Station and Train workspaces record them)
  --demo                replay the tutorial's own demonstration (its DEMO statement)
  --profile P           the station profile for the log: a .json file or the name of
                        one of the model's profiles (default: the tutorial's PROFILE)
  --autopilot PATH --record OUT [--camera CAM]
                        fly the joint targets of PATH with the levers of a virtual
                        console and record them to OUT (a demonstration; see
                        docs/training.md), and a chase camera to CAM, then print
                        the result of that run
  --lang es|en          language of the tutorial's texts and of the messages
                        (default: the system's; an option of every command)
  --json                print the result as one JSON object

Without --input, --demo or --autopilot it only checks the tutorial and its model.

Exit status: 0 the tutorial is fine (checked) or the run passed; 1 the run failed;
2 bad input: a usage error, a tutorial with errors, an unreadable log.
</source>
        <translation>Uso: padrob tutorial ARCHIVO [--input REGISTRO | --demo] [OPCIONES]

Revisa un archivo de tutorial (.tut) y, con --input o --demo, lo ejecuta sin ventana:
el registro de entradas se reproduce a través del perfil del puesto en la simulación
mientras el evaluador del tutorial vigila los objetivos, el agarre, las colisiones,
las sobrecargas y el tiempo, y asigna el puntaje. Informa si aprobó, el desglose del
puntaje y los eventos con sus tiempos.

  --input REGISTRO      reproduce este registro de entradas (lecturas crudas de los
                        dispositivos, como las graban los espacios Puesto y
                        Entrenamiento de padrob-studio)
  --demo                reproduce la demostración del propio tutorial (su DEMO)
  --profile P           el perfil del puesto para el registro: un archivo .json o el
                        nombre de uno de los perfiles del modelo (por omisión: el
                        PROFILE del tutorial)
  --autopilot RUTA --record SALIDA [--camera CÁMARA]
                        recorre los objetivos de articulación de RUTA con las palancas
                        de una consola virtual y los graba en SALIDA (una
                        demostración; vea docs/training.md), y una cámara de
                        seguimiento en CÁMARA, y luego informa el resultado
  --lang es|en          idioma de los textos del tutorial y de los mensajes (por
                        omisión: el del sistema; una opción de todos los comandos)
  --json                escribe el resultado como un objeto JSON

Sin --input, --demo ni --autopilot solo revisa el tutorial y su modelo.

Estado de salida: 0 el tutorial está bien (revisado) o la ejecución aprobó; 1 la
ejecución reprobó; 2 entrada inválida: un error de uso, un tutorial con errores, un
registro ilegible.
</translation>
    </message>
    <message>
        <location line="+36" />
        <source>every goal done</source>
        <translation>todos los objetivos cumplidos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the time ran out</source>
        <translation>se acabó el tiempo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a hard hit</source>
        <translation>un golpe fuerte</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a worker was touched</source>
        <translation>se tocó a un trabajador</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the input ended</source>
        <translation>terminó la entrada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the simulation failed</source>
        <translation>falló la simulación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>stopped</source>
        <translation>detenido</translation>
    </message>
    <message>
        <location line="+9" />
        <source>PASSED</source>
        <translation>APROBADO</translation>
    </message>
    <message>
        <location line="+0" />
        <source>FAILED</source>
        <translation>REPROBADO</translation>
    </message>
    <message>
        <location line="+2" />
        <source>score %1/100 (pass mark %2), %3 s, %4/%5 goals, end: %6</source>
        <translation>puntaje %1/100 (aprobación %2), %3 s, %4/%5 objetivos, fin: %6</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 s (par %2 s, limit %3 s)</source>
        <translation>%1 s (referencia %2 s, límite %3 s)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 % efficient (%2 m, ideal %3 m)</source>
        <translation>%1 % de eficiencia (%2 m, ideal %3 m)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>RMS jerk %1 m/s3 (zero points at %2)</source>
        <translation>tirón RMS %1 m/s3 (cero puntos en %2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 penalty points</source>
        <translation>%1 puntos de penalización</translation>
    </message>
    <message>
        <location line="+4" />
        <source>events:</source>
        <translation>eventos:</translation>
    </message>
    <message>
        <location line="+7" />
        <source>to improve:</source>
        <translation>para mejorar:</translation>
    </message>
    <message>
        <location line="+95" />
        <source>one tutorial file at a time</source>
        <translation>un archivo de tutorial a la vez</translation>
    </message>
    <message>
        <location line="+3" />
        <source>no tutorial file given</source>
        <translation>no se indicó ningún archivo de tutorial</translation>
    </message>
    <message>
        <location line="+2" />
        <source>--input, --demo and --autopilot exclude each other</source>
        <translation>--input, --demo y --autopilot se excluyen entre sí</translation>
    </message>
    <message>
        <location line="+2" />
        <source>--autopilot and --record go together</source>
        <translation>--autopilot y --record van juntos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--camera goes with --autopilot</source>
        <translation>--camera va con --autopilot</translation>
    </message>
    <message numerus="yes">
        <location line="+10" />
        <source>OK (%n goal(s), no demonstration)</source>
        <translation>
            <numerusform>correcto (%n objetivo, sin demostración)</numerusform>
            <numerusform>correcto (%n objetivos, sin demostración)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>OK (%n goal(s))</source>
        <translation>
            <numerusform>correcto (%n objetivo)</numerusform>
            <numerusform>correcto (%n objetivos)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+47" />
        <source>the tutorial has no usable demonstration (DEMO)</source>
        <translation>el tutorial no tiene una demostración utilizable (DEMO)</translation>
    </message>
    <message>
        <location filename="../ide/cli/centre.cpp" line="-681" />
        <source>--domain must be a whole number from 0 to 232, not '%1'</source>
        <translation>--domain debe ser un número entero de 0 a 232, no '%1'</translation>
    </message>
    <message>
        <location line="+52" />
        <location line="+10" />
        <source>--records-server must be USER@HOST:PORT/DATABASE, not '%1'</source>
        <translation>--records-server debe ser USUARIO@SERVIDOR:PUERTO/BASE, no '%1'</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Usage: padrob station TUTORIAL... --name NAME [OPTIONS]

Runs a training station without a window on the centre's network: the tutorials'
machine is simulated in real time, its state is streamed for display nodes
(padrob-studio --display-of NAME) and the instructor, its events are sent as they
happen, and the instructor's signed commands are obeyed: start, pause, resume,
reset and stop a tutorial, inject and clear faults. Every attempt is recorded.
Runs until interrupted (Ctrl+C or SIGTERM), then says it is leaving.

  --name NAME           the station's name, unique in the centre
  --profile P           the operator's devices: a station profile of the model (its
                        name, or a .json file; docs/station.md): gamepads, joysticks,
                        the serial valve console
  --demo                the operator's input is each tutorial's demonstration
                        (a showcase, or a test)
                        Without either, the levers rest.
  --records FILE        record the attempts in this SQLite file (the station's journal)
  --records-server USER@HOST:PORT/DATABASE
                        and sync them to the centre's PostgreSQL server; while it is
                        out of reach the journal keeps them (docs/records.md)
  --records-password FILE
                        the server's password, sealed with the centre's key by
                        'padrob centre seal' (never stored in plain text)
  --for SECONDS         stop after this long
</source>
        <translation>Uso: padrob station TUTORIAL... --name NOMBRE [OPCIONES]

Ejecuta una estación de entrenamiento sin ventana en la red del centro: la máquina
de los tutoriales se simula en tiempo real, su estado se transmite a los nodos de
pantalla (padrob-studio --display-of NOMBRE) y al instructor, sus eventos se envían
a medida que ocurren, y obedece las órdenes firmadas del instructor: iniciar,
pausar, reanudar, reiniciar y detener un tutorial, inyectar y quitar fallas. Cada
intento queda registrado. Funciona hasta que se interrumpe (Ctrl+C o SIGTERM), y
entonces avisa que se va.

  --name NOMBRE         el nombre de la estación, único en el centro
  --profile P           los dispositivos del operador: un perfil de estación del
                        modelo (su nombre, o un archivo .json; docs/station.md):
                        gamepads, joysticks, la consola de válvulas serial
  --demo                la entrada del operador es la demostración de cada tutorial
                        (una exhibición, o una prueba)
                        Sin ninguna de las dos, las palancas quedan en reposo.
  --records ARCHIVO     registra los intentos en este archivo SQLite (el registro
                        local de la estación)
  --records-server USUARIO@SERVIDOR:PUERTO/BASE
                        y los sincroniza con el servidor PostgreSQL del centro;
                        mientras no se alcanza, el registro local los guarda
                        (docs/records.md)
  --records-password ARCHIVO
                        la contraseña del servidor, sellada con la clave del centro
                        por 'padrob centre seal' (nunca guardada en texto plano)
  --for SEGUNDOS        se detiene después de ese tiempo
</translation>
    </message>
    <message>
        <location line="+61" />
        <source>--for must be a positive number of seconds, not '%1'</source>
        <translation>--for debe ser un número positivo de segundos, no '%1'</translation>
    </message>
    <message>
        <location line="+8" />
        <source>--name is required: the station's name in the centre</source>
        <translation>falta --name: el nombre de la estación en el centro</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give at least one tutorial file (.tut)</source>
        <translation>indique al menos un archivo de tutorial (.tut)</translation>
    </message>
    <message>
        <location line="-175" />
        <source>Network options (every node of a centre uses the same):
  --domain N            the centre's DDS domain, 0-232 (default 0)
  --key FILE            the centre's key (make one with 'padrob centre key FILE'):
                        every node signs what it says with it and ignores what is
                        not signed with it; stations refuse commands without it
  --interface NAME      the network interface to use (name or address; repeatable)
  --peer ADDRESS        discover the other computers by unicast at ADDRESS
                        (repeatable; without it, multicast)
  --loopback            this computer only (--interface 127.0.0.1 --peer 127.0.0.1)
  --security DIR        DDS Security: authenticated, access-controlled, encrypted
                        traffic, with the centre's PKI in DIR and this node's
                        identity in DIR/nodes/NAME (see 'padrob centre pki')
</source>
        <translation>Opciones de red (todos los nodos de un centro usan las mismas):
  --domain N            el dominio DDS del centro, 0-232 (por omisión 0)
  --key ARCHIVO         la clave del centro (se crea con 'padrob centre key ARCHIVO'):
                        cada nodo firma con ella lo que dice e ignora lo que no esté
                        firmado con ella; las estaciones rechazan las órdenes sin ella
  --interface NOMBRE    la interfaz de red a usar (nombre o dirección; repetible)
  --peer DIRECCIÓN      descubre los otros computadores por unicast en DIRECCIÓN
                        (repetible; sin ella, multicast)
  --loopback            solo este computador (--interface 127.0.0.1 --peer 127.0.0.1)
  --security CARPETA    DDS Security: tráfico autenticado, con control de acceso y
                        cifrado, con la PKI del centro en CARPETA y la identidad de
                        este nodo en CARPETA/nodes/NOMBRE (vea 'padrob centre pki')
</translation>
    </message>
    <message>
        <location line="+177" />
        <source>--key FILE is required: the centre's key signs what the station says (no instructor or display believes it otherwise) and checks the instructor's commands</source>
        <translation>se requiere --key ARCHIVO: la clave del centro firma lo que dice la estación (sin ella ningún instructor ni pantalla le cree) y verifica las órdenes del instructor</translation>
    </message>
    <message>
        <location line="+35" />
        <source>cannot open the sealed password in %1: it must be made by 'padrob centre seal' with this centre's key</source>
        <translation>no se puede abrir la contraseña sellada de %1: debe crearse con 'padrob centre seal' y la clave de este centro</translation>
    </message>
    <message>
        <location line="+10" />
        <source>--records-server needs --records FILE, the station's local journal</source>
        <translation>--records-server necesita --records ARCHIVO, el registro local de la estación</translation>
    </message>
    <message>
        <location line="+35" />
        <source>station %1: %2
</source>
        <translation>estación %1: %2
</translation>
    </message>
    <message>
        <location line="+18" />
        <source>station %1: on the centre's network (domain %2), ready
</source>
        <translation>estación %1: en la red del centro (dominio %2), lista
</translation>
    </message>
    <message>
        <location line="+4" />
        <source>station %1: left the centre's network
</source>
        <translation>estación %1: salió de la red del centro
</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Usage: padrob instructor list|watch|send ... [OPTIONS]

The instructor's station without a window:
  list [--wait S]       the stations on the network after listening S seconds
                        (default 2): name, status, tutorial, time, score, warnings
  watch [--for S]       print the stations' events and comings and goings as they
                        happen (for S seconds; default until interrupted)
  send STATION COMMAND [ARG [ARG2]] [--value V] [--timeout S]
                        send a signed command and wait for the station's answer:
                          start [TUTORIAL [OPERATOR]], pause, resume, reset, stop,
                          inject FAULT [DRIVE|X,Y,Z], clear FAULT [DRIVE]
                        faults: hose-burst DRIVE, stuck-valve DRIVE [--value U],
                          worker-in X,Y,Z [--value WORKER], power-cut
  --name NAME           the instructor's name (default: instructor@HOST)
  --json                JSON output (one object; watch: one per line)

Exit status: 0 done or accepted, 1 the station refused or did not answer,
2 usage error.
</source>
        <translation>Uso: padrob instructor list|watch|send ... [OPCIONES]

El puesto del instructor sin ventana:
  list [--wait S]       las estaciones de la red tras escuchar S segundos
                        (por omisión 2): nombre, estado, tutorial, tiempo, puntaje, avisos
  watch [--for S]       muestra los eventos de las estaciones y sus llegadas y salidas
                        a medida que ocurren (durante S segundos; por omisión hasta
                        que se interrumpa)
  send ESTACIÓN ORDEN [ARG [ARG2]] [--value V] [--timeout S]
                        envía una orden firmada y espera la respuesta de la estación:
                          start [TUTORIAL [OPERADOR]], pause, resume, reset, stop,
                          inject FALLA [ACCIONAMIENTO|X,Y,Z], clear FALLA [ACCIONAMIENTO]
                        fallas: hose-burst ACCIONAMIENTO, stuck-valve ACCIONAMIENTO
                          [--value U], worker-in X,Y,Z [--value TRABAJADOR], power-cut
  --name NOMBRE         el nombre del instructor (por omisión: instructor@SERVIDOR)
  --json                salida JSON (un objeto; watch: uno por línea)

Estado de salida: 0 hecho o aceptado, 1 la estación rechazó o no respondió,
2 error de uso.
</translation>
    </message>
    <message>
        <location line="+24" />
        <source>on the network</source>
        <translation>en la red</translation>
    </message>
    <message>
        <location line="+1" />
        <source>silent</source>
        <translation>en silencio</translation>
    </message>
    <message>
        <location line="+1" />
        <source>gone (it left)</source>
        <translation>fuera (se retiró)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>idle</source>
        <translation>inactiva</translation>
    </message>
    <message>
        <location line="+1" />
        <source>running</source>
        <translation>en curso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>paused</source>
        <translation>en pausa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ended</source>
        <translation>terminado</translation>
    </message>
    <message>
        <location line="+70" />
        <source>the station has no centre key and takes no commands</source>
        <translation>la estación no tiene clave del centro y no acepta órdenes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the signature does not match the station's centre key</source>
        <translation>la firma no corresponde a la clave del centro de la estación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the command is too old or from the future (check the computers' clocks)</source>
        <translation>la orden es demasiado antigua o del futuro (revise los relojes de los computadores)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a replayed command (its nonce was already used)</source>
        <translation>una orden repetida (su número único ya se usó)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a field of the command is longer than the centre allows</source>
        <translation>un campo de la orden es más largo de lo que el centro permite</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station took too many commands in the last 30 s; try again shortly</source>
        <translation>la estación recibió demasiadas órdenes en los últimos 30 s; intente de nuevo en un momento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station has no such tutorial</source>
        <translation>la estación no tiene ese tutorial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no attempt is running</source>
        <translation>no hay ningún intento en curso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the attempt is not paused</source>
        <translation>el intento no está en pausa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no such fault (hose-burst, stuck-valve, worker-in, power-cut)</source>
        <translation>no existe esa falla (hose-burst, stuck-valve, worker-in, power-cut)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no such command</source>
        <translation>no existe esa orden</translation>
    </message>
    <message>
        <location line="+36" />
        <location line="+264" />
        <source>%1 needs a number</source>
        <translation>%1 necesita un número</translation>
    </message>
    <message>
        <location line="-256" />
        <source>say what to do: list, watch or send</source>
        <translation>indique qué hacer: list, watch o send</translation>
    </message>
    <message>
        <location line="+3" />
        <source>unknown instructor command '%1'</source>
        <translation>orden de instructor desconocida '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>send needs a station and a command</source>
        <translation>send necesita una estación y una orden</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the centre's key is required (--key FILE): what the stations say is signed with it, and so are the commands</source>
        <translation>se requiere la clave del centro (--key ARCHIVO): lo que dicen las estaciones se firma con ella, y también las órdenes</translation>
    </message>
    <message>
        <location line="+156" />
        <location line="+4" />
        <source>expected: padrob centre key --key CENTRE-KEY --node NAME FILE</source>
        <translation>se esperaba: padrob centre key --key CLAVE-DEL-CENTRO --node NOMBRE ARCHIVO</translation>
    </message>
    <message>
        <location line="+8" />
        <source>node %1's key in %2 (fingerprint %3), from the centre key %4
</source>
        <translation>clave del nodo %1 en %2 (huella %3), a partir de la clave del centro %4
</translation>
    </message>
    <message>
        <location line="+90" />
        <source>no tutorial file %1 (give --tutorial FILE)</source>
        <translation>no existe el archivo de tutorial %1 (use --tutorial ARCHIVO)</translation>
    </message>
    <message>
        <location line="-223" />
        <source>no station answered
</source>
        <translation>ninguna estación respondió
</translation>
    </message>
    <message>
        <location line="+18" />
        <source>%1 is %2
</source>
        <translation>%1 está %2
</translation>
    </message>
    <message>
        <location line="+16" />
        <source>station %1 did not answer</source>
        <translation>la estación %1 no respondió</translation>
    </message>
    <message>
        <location line="+30" />
        <source>station %1 did not answer the command</source>
        <translation>la estación %1 no respondió la orden</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: %2 done
</source>
        <translation>%1: %2 hecho
</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 refused %2: %3
</source>
        <translation>%1 rechazó %2: %3
</translation>
    </message>
    <message>
        <location line="+65" />
        <source>expected: padrob centre seal --key FILE</source>
        <translation>se esperaba: padrob centre seal --key ARCHIVO</translation>
    </message>
    <message>
        <location line="+10" />
        <source>give the secret on standard input (one line)</source>
        <translation>entregue el secreto por la entrada estándar (una línea)</translation>
    </message>
    <message>
        <location line="+20" />
        <source>expected: padrob centre pki DIR [--node NAME]...</source>
        <translation>se esperaba: padrob centre pki CARPETA [--node NOMBRE]...</translation>
    </message>
    <message>
        <location line="+8" />
        <source>new centre PKI in %1 (identity CA, permissions CA, signed governance)
</source>
        <translation>nueva PKI del centro en %1 (CA de identidad, CA de permisos, gobernanza firmada)
</translation>
    </message>
    <message>
        <location line="+7" />
        <source>identity and permissions of node %1 in %2
</source>
        <translation>identidad y permisos del nodo %1 en %2
</translation>
    </message>
    <message>
        <location line="+21" />
        <source>--stations needs a whole number from 1 to 64</source>
        <translation>--stations necesita un número entero de 1 a 64</translation>
    </message>
    <message>
        <location line="+96" />
        <source>only %1 of %2 stations were heard</source>
        <translation>solo se oyeron %1 de %2 estaciones</translation>
    </message>
    <message>
        <location line="+61" />
        <source>%1 stations streaming to one instructor for %2 s (%3 states):
</source>
        <translation>%1 estaciones transmitiendo a un instructor durante %2 s (%3 estados):
</translation>
    </message>
    <message>
        <location line="+2" />
        <source>  state rate per station: median %1 Hz, lowest %2 Hz; most lost: %3 %
</source>
        <translation>  frecuencia de estados por estación: mediana %1 Hz, mínima %2 Hz; la mayor pérdida: %3 %
</translation>
    </message>
    <message>
        <location line="+2" />
        <source>  latency, station to instructor: median %1 ms, 99th percentile %2 ms, max %3 ms
</source>
        <translation>  latencia, de estación a instructor: mediana %1 ms, percentil 99 %2 ms, máxima %3 ms
</translation>
    </message>
    <message>
        <location line="+2" />
        <source>  CPU: the instructor %1 % of a core; each station (median) %2 %
</source>
        <translation>  CPU: el instructor %1 % de un núcleo; cada estación (mediana) %2 %
</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Usage: padrob centre key FILE
       padrob centre key --key CENTRE-KEY --node NAME FILE
       padrob centre seal --key FILE &lt; SECRET
       padrob centre bench [--stations N] [--seconds S] [--tutorial FILE] [--json]
       padrob centre pki DIR [--node NAME]...

key: makes a new centre key (32 random bytes) in FILE, readable by its owner only.
Copy it to every station, instructor and display of the centre (padrob station
--key, padrob instructor --key, padrob-studio --centre-key): every message is
signed with it, and what is not is ignored (commands: refused). An existing file
is never replaced. With --node NAME: node NAME's own key, derived from the
centre's key, for a station (padrob station --name NAME --key FILE): it signs
only that station's messages and checks only the commands for it, so the
station cannot pass for another. Instructors keep the centre's key.

seal: prints the line read from standard input (the records server's password)
sealed with the centre's key, for padrob station --records-password FILE.

bench: starts N headless stations (default 16) on this computer, each running the
tutorial's demonstration in real time and streaming its state at 60 Hz, and measures
at one instructor the state rate, the latency from station to instructor and the CPU
used (docs/performance.md).

pki: makes the centre's PKI for DDS Security in DIR (an identity CA, a permissions
CA and the signed governance document); with --node NAME, issues node NAME's
identity and permissions (valid 10 years) in DIR/nodes/NAME. Copy to each node
identity_ca.pem, permissions_ca.pem, governance.p7s and its nodes/NAME folder,
never the .key files of the CAs; then run it with --security DIR.
</source>
        <translation>Uso: padrob centre key ARCHIVO
       padrob centre key --key CLAVE-DEL-CENTRO --node NOMBRE ARCHIVO
       padrob centre seal --key ARCHIVO &lt; SECRETO
       padrob centre bench [--stations N] [--seconds S] [--tutorial ARCHIVO] [--json]
       padrob centre pki CARPETA [--node NOMBRE]...

key: crea una nueva clave del centro (32 bytes al azar) en ARCHIVO, legible solo por
su dueño. Cópiela a cada estación, instructor y pantalla del centro (padrob station
--key, padrob instructor --key, padrob-studio --centre-key): cada mensaje se firma
con ella, y lo que no lo esté se ignora (las órdenes: se rechazan). Un archivo
existente nunca se reemplaza. Con --node NOMBRE: la clave propia del nodo NOMBRE,
derivada de la clave del centro, para una estación (padrob station --name NOMBRE
--key ARCHIVO): firma solo los mensajes de esa estación y verifica solo las órdenes
para ella, de modo que la estación no puede hacerse pasar por otra. Los instructores
conservan la clave del centro.

seal: muestra la línea leída de la entrada estándar (la contraseña del servidor de
registros) sellada con la clave del centro, para padrob station --records-password
ARCHIVO.

bench: inicia N estaciones sin ventana (por omisión 16) en este computador, cada una
ejecutando la demostración del tutorial en tiempo real y transmitiendo su estado a
60 Hz, y mide en un instructor la frecuencia de estados, la latencia de estación a
instructor y la CPU usada (docs/performance.md).

pki: crea la PKI del centro para DDS Security en CARPETA (una CA de identidad, una CA
de permisos y el documento de gobernanza firmado); con --node NOMBRE, emite la
identidad y los permisos del nodo NOMBRE (válidos 10 años) en CARPETA/nodes/NOMBRE.
Copie a cada nodo identity_ca.pem, permissions_ca.pem, governance.p7s y su carpeta
nodes/NOMBRE, nunca los archivos .key de las CA; luego ejecútelo con --security CARPETA.
</translation>
    </message>
    <message>
        <location line="+30" />
        <source>expected: padrob centre key FILE</source>
        <translation>se esperaba: padrob centre key ARCHIVO</translation>
    </message>
    <message>
        <location line="+9" />
        <source>new centre key in %1 (fingerprint %2)
</source>
        <translation>nueva clave del centro en %1 (huella %2)
</translation>
    </message>
</context>
<context>
    <name>studio::AttemptScreen</name>
    <message>
        <location filename="../ide/studio/train/attempt_screen.cpp" line="+168" />
        <source>Esc or Stop ends the attempt.</source>
        <translation>Esc o Detener termina el intento.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Show the expert</source>
        <translation>Mostrar al experto</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Your trainer chooses whether the expert is shown.</source>
        <translation>Su instructor decide si se muestra al experto.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The demonstration runs beside the attempt, drawn translucent.</source>
        <translation>La demostración corre junto al intento, dibujada translúcida.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hydraulics</source>
        <translation>Hidráulica</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The pump, the spools and the chamber pressures beside the view.</source>
        <translation>La bomba, las correderas y las presiones de las cámaras junto a la vista.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>View:</source>
        <translation>Vista:</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Three screens (−60°, 0°, +60°)</source>
        <translation>Tres pantallas (−60°, 0°, +60°)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <location line="+69" />
        <source>Controls:</source>
        <translation>Mandos:</translation>
    </message>
    <message>
        <location line="+101" />
        <source>Goal %1 of %2</source>
        <translation>Objetivo %1 de %2</translation>
    </message>
    <message>
        <location line="+57" />
        <source>Distance: %1 m</source>
        <translation>Distancia: %1 m</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Angle: %1° off (within %2°)</source>
        <translation>Ángulo: %1° de desvío (tolerancia %2°)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Hold: %1 s more</source>
        <translation>Mantener: %1 s más</translation>
    </message>
    <message>
        <location line="+4" />
        <source>come within %1 m</source>
        <translation>se acerque a menos de %1 m</translation>
    </message>
    <message>
        <location line="+2" />
        <source>align the load: %1° off</source>
        <translation>alinee la carga: %1° de desvío</translation>
    </message>
    <message>
        <location line="+0" />
        <source>align the head: %1° off</source>
        <translation>alinee el cabezal: %1° de desvío</translation>
    </message>
    <message>
        <location line="+2" />
        <source>hold the load in the claws</source>
        <translation>tenga la carga en las garras</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hold %1 s</source>
        <translation>Mantenga %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hold %1 s once you %2</source>
        <translation>Mantenga %1 s cuando %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source> and </source>
        <translation> y </translation>
    </message>
    <message>
        <location line="-71" />
        <source>All goals done</source>
        <translation>Todos los objetivos cumplidos</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Time: %1 / %2 s</source>
        <translation>Tiempo: %1 / %2 s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Penalties: %1</source>
        <translation>Penalizaciones: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Load in the claws</source>
        <translation>Carga en las garras</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Paused by the instructor</source>
        <translation>En pausa por el instructor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Overload: a relief valve is open</source>
        <translation>Sobrecarga: una válvula de alivio está abierta</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Too close to a worker (%1 m)</source>
        <translation>Demasiado cerca de un trabajador (%1 m)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Clearance %1 m</source>
        <translation>Holgura %1 m</translation>
    </message>
</context>
<context>
    <name>studio::CalibrationWizard</name>
    <message>
        <location filename="../ide/studio/station/calibration_wizard.cpp" line="+70" />
        <source>Axis %1</source>
        <translation>Eje %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Calibrate %1 of %2</source>
        <translation>Calibrar %1 de %2</translation>
    </message>
    <message>
        <location line="+68" />
        <source>Leave the lever at rest</source>
        <translation>Deje la palanca en reposo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Let go of the lever (or stick) and leave it where it rests by itself. Its reading over the next moments is the centre of the channel.</source>
        <translation>Suelte la palanca (o el joystick) y déjela donde queda en reposo por sí sola. Su lectura durante los próximos instantes es el centro del canal.</translation>
    </message>
    <message>
        <location line="+274" />
        <source>Capturing… %p%</source>
        <translation>Capturando… %p%</translation>
    </message>
    <message>
        <location line="-272" />
        <source>Capture again</source>
        <translation>Capturar de nuevo</translation>
    </message>
    <message>
        <location line="-69" />
        <source>&lt; &amp;Back</source>
        <translation>&lt; &amp;Atrás</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Next &gt;</source>
        <translation>&amp;Siguiente &gt;</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Finish</source>
        <translation>&amp;Finalizar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location line="+67" />
        <source>Forget these readings and capture the rest position anew</source>
        <translation>Descartar estas lecturas y capturar de nuevo la posición de reposo</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Move the lever to its full travel, both ways</source>
        <translation>Lleve la palanca a todo su recorrido, en ambos sentidos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Push the lever slowly all the way to one end, then all the way to the other, and let it come back to rest. A lever that only moves one way (a trigger, a pedal) is fine: move it to its end.</source>
        <translation>Empuje la palanca lentamente hasta un extremo, luego hasta el otro, y déjela volver al reposo. Una palanca que se mueve en un solo sentido (un gatillo, un pedal) sirve igual: llévela hasta su extremo.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The reading now; the red marks are the farthest seen each way</source>
        <translation>La lectura actual; las marcas rojas son lo más lejos que llegó en cada sentido</translation>
    </message>
    <message>
        <location line="+72" />
        <source>Dead band, direction and response</source>
        <translation>Banda muerta, sentido y respuesta</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fraction of the travel below the centre where the output stays 0</source>
        <translation>Fracción del recorrido bajo el centro donde la salida se mantiene en 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fraction of the travel above the centre where the output stays 0</source>
        <translation>Fracción del recorrido sobre el centro donde la salida se mantiene en 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Dead band below centre:</source>
        <translation>Banda muerta bajo el centro:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Dead band above centre:</source>
        <translation>Banda muerta sobre el centro:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inverted</source>
        <translation>Invertido</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pushing the lever towards its maximum reading gives a negative command</source>
        <translation>Al empujar la palanca hacia su lectura máxima se obtiene un comando negativo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Linear</source>
        <translation>Lineal</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Exponential</source>
        <translation>Exponencial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Exponential: finer control near the centre</source>
        <translation>Exponencial: control más fino cerca del centro</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Response:</source>
        <translation>Respuesta:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>k of y = (e^(k·x) − 1)/(e^k − 1): larger is finer near the centre</source>
        <translation>k de y = (e^(k·x) − 1)/(e^k − 1): mayor es más fino cerca del centro</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Curve parameter k:</source>
        <translation>Parámetro k de la curva:</translation>
    </message>
    <message>
        <location line="+1" />
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1" />
        <source>off</source>
        <translation>desactivado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Low-pass cutoff frequency against a noisy pot (0: no filter)</source>
        <translation>Frecuencia de corte del filtro pasa bajos contra un potenciómetro con ruido (0: sin filtro)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Low-pass filter:</source>
        <translation>Filtro pasa bajos:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Keep this calibration for</source>
        <translation>Guardar esta calibración para</translation>
    </message>
    <message>
        <location line="+1" />
        <source>This device only (%1)</source>
        <translation>Solo este dispositivo (%1)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Only this very device uses it</source>
        <translation>Solo este mismo dispositivo la usa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Any %1</source>
        <translation>Cualquier %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Every device of this kind uses it, so the profile works with another one of the same make (profile key “%1”)</source>
        <translation>Todos los dispositivos de este tipo la usan, así el perfil funciona con otro de la misma marca (clave del perfil “%1”)</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Raw:</source>
        <translation>Bruto:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Calibrated:</source>
        <translation>Calibrado:</translation>
    </message>
    <message>
        <location line="+45" />
        <source>%1 is not there any more.</source>
        <translation>%1 ya no está conectado.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: %2 — waiting for it.</source>
        <translation>%1: %2 — esperándolo.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 has no channel %2.</source>
        <translation>%1 no tiene canal %2.</translation>
    </message>
    <message>
        <location line="+71" />
        <source>Captured</source>
        <translation>Capturado</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Reading: %1</source>
        <translation>Lectura: %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Waiting for readings…</source>
        <translation>Esperando lecturas…</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Reading: %1    Centre: %2    Spread: %3 (%4 % of the travel)</source>
        <translation>Lectura: %1    Centro: %2    Dispersión: %3 (%4 % del recorrido)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The reading moves while the lever rests: a noisy pot or a loose wire? A dead band or the low-pass filter will hide some of it.</source>
        <translation>La lectura varía con la palanca en reposo: ¿un potenciómetro con ruido o un cable suelto? Una banda muerta o el filtro pasa bajos ocultarán parte de esto.</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Reading: %1    Centre: %2    Seen: %3 … %4</source>
        <translation>Lectura: %1    Centro: %2    Recorrido visto: %3 … %4</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Enough travel seen. Keep moving to reach the very ends, then press Next.</source>
        <translation>Recorrido suficiente. Siga moviendo la palanca hasta los extremos y luego presione Siguiente.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Captured: minimum %1, centre %2, maximum %3.</source>
        <translation>Capturado: mínimo %1, centro %2, máximo %3.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>One-sided: the output goes from 0 to 1.</source>
        <translation>De un solo sentido: la salida va de 0 a 1.</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Raw %1 → %2</source>
        <translation>Bruto %1 → %2</translation>
    </message>
</context>
<context>
    <name>studio::ChannelPanel</name>
    <message>
        <location filename="../ide/studio/station/channel_bars.cpp" line="+228" />
        <location line="+23" />
        <source>No device selected</source>
        <translation>Ningún dispositivo seleccionado</translation>
    </message>
    <message>
        <location line="-24" />
        <source>Buttons</source>
        <translation>Botones</translation>
    </message>
    <message>
        <location line="-2" />
        <source>Keys are digital: a key gives its drive the full command (−1, 0 or +1) at once, so there is nothing to calibrate. A ramp eases each key's command in and out instead.</source>
        <translation>Las teclas son digitales: una tecla da a su accionamiento la orden completa (−1, 0 o +1) al instante, así que no hay nada que calibrar. En su lugar, una rampa suaviza la orden de cada tecla al subir y al bajar.</translation>
    </message>
    <message>
        <location line="+36" />
        <source>%1: no channels (yet)</source>
        <translation>%1: sin canales (todavía)</translation>
    </message>
    <message numerus="yes">
        <location line="+2" />
        <source>%1: %n channel(s)</source>
        <translation>
            <numerusform>%1: %n canal</numerusform>
            <numerusform>%1: %n canales</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1" />
        <source>Channel</source>
        <translation>Canal</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Raw reading</source>
        <translation>Lectura en bruto</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Calibrated</source>
        <translation>Calibrado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ramp</source>
        <translation>Rampa</translation>
    </message>
    <message>
        <location line="+29" />
        <location line="+91" />
        <source>not calibrated</source>
        <translation>sin calibrar</translation>
    </message>
    <message>
        <location line="-84" />
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>at once</source>
        <translation>al instante</translation>
    </message>
    <message>
        <location line="+1" />
        <source>How long a key takes to open its valve fully (and to close it again): 0 gives the full command at once</source>
        <translation>Cuánto tarda una tecla en abrir del todo su válvula (y en volver a cerrarla): 0 da la orden completa al instante</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Calibrate…</source>
        <translation>Calibrar…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Capture this channel's centre and travel, and set its dead band and curve</source>
        <translation>Capturar el centro y el recorrido de este canal, y ajustar su banda muerta y su curva</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Button %1: %2</source>
        <translation>Botón %1: %2</translation>
    </message>
    <message>
        <location line="+52" />
        <source>out of range</source>
        <translation>fuera de rango</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The reading is beyond the calibrated range: the pot slipped, a wire is loose, or the calibration is stale. Calibrate again.</source>
        <translation>La lectura está fuera del rango calibrado: el potenciómetro se desplazó, hay un cable suelto o la calibración quedó desactualizada. Calibre de nuevo.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The device's nominal range is in use until this channel is calibrated</source>
        <translation>Se usa el rango nominal del dispositivo hasta que este canal se calibre</translation>
    </message>
</context>
<context>
    <name>studio::CourseScreen</name>
    <message>
        <location filename="../ide/studio/train/course_screen.cpp" line="+25" />
        <source>Training course</source>
        <translation>Curso de entrenamiento</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Operator:</source>
        <translation>Operador:</translation>
    </message>
    <message>
        <location line="+8" />
        <source>name or number</source>
        <translation>nombre o número</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Records</source>
        <translation>Registros</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The trainee records: operators, attempts, progress (for the trainer).</source>
        <translation>Los registros de aprendices: operadores, intentos, avance (para el instructor).</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Open</source>
        <translation>Abrir</translation>
    </message>
    <message>
        <location line="+47" />
        <source>Level %1 — %2</source>
        <translation>Nivel %1 — %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>(cannot be used)</source>
        <translation>(no se puede usar)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>This tutorial cannot be loaded.</source>
        <translation>Este tutorial no se puede cargar.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(locked: pass the level before)</source>
        <translation>(bloqueado: apruebe el nivel anterior)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Pass every stage of the level before to unlock this one.</source>
        <translation>Apruebe todas las etapas del nivel anterior para desbloquear esta.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>best %1 of 100</source>
        <translation>mejor %1 de 100</translation>
    </message>
</context>
<context>
    <name>studio::CurvePlot</name>
    <message>
        <location filename="../ide/studio/station/curve_plot.cpp" line="+118" />
        <source>raw reading → output (shaded: dead band)</source>
        <translation>lectura en bruto → salida (sombreado: banda muerta)</translation>
    </message>
</context>
<context>
    <name>studio::DebriefScreen</name>
    <message>
        <location filename="../ide/studio/train/debrief_screen.cpp" line="+58" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+97" />
        <location line="+24" />
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location line="-24" />
        <location line="+24" />
        <location line="+24" />
        <location line="+23" />
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <location line="-70" />
        <source>Events</source>
        <translation>Eventos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>You and the expert</source>
        <translation>Usted y el experto</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Measure</source>
        <translation>Medida</translation>
    </message>
    <message>
        <location line="+0" />
        <source>You</source>
        <translation>Usted</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Expert</source>
        <translation>Experto</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back to the result</source>
        <translation>Volver al resultado</translation>
    </message>
    <message>
        <location line="+56" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+40" />
        <source>%1 s — %2</source>
        <translation>%1 s — %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>No events.</source>
        <translation>Sin eventos.</translation>
    </message>
    <message>
        <location line="+44" />
        <source>Force of %1</source>
        <translation>Fuerza de %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>No drive force</source>
        <translation>Sin fuerza de accionamiento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>kN</source>
        <translation>kN</translation>
    </message>
    <message>
        <location line="+0" />
        <source>kN·m</source>
        <translation>kN·m</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Relief valves open</source>
        <translation>Válvulas de alivio abiertas</translation>
    </message>
    <message>
        <location line="+0" />
        <source>valves</source>
        <translation>válvulas</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Time [s]</source>
        <translation>Tiempo [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Path length [m]</source>
        <translation>Recorrido [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Overshoot [m]</source>
        <translation>Sobrepaso [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RMS jerk [m/s³]</source>
        <translation>Tirón RMS [m/s³]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Score</source>
        <translation>Puntaje</translation>
    </message>
    <message>
        <location line="+8" />
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location line="+0" />
        <source>none</source>
        <translation>ninguno</translation>
    </message>
</context>
<context>
    <name>studio::DisplayFeed</name>
    <message>
        <location filename="../ide/studio/centre/display_feed.cpp" line="+174" />
        <source>The station announced no usable model name (“%1”).</source>
        <translation>El puesto no anunció un nombre de modelo utilizable («%1»).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The station's model “%1” is not installed on this computer (%2).</source>
        <translation>El modelo «%1» del puesto no está instalado en este computador (%2).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The model file %1 cannot be read.</source>
        <translation>No se puede leer el archivo de modelo %1.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The station runs another version of the model “%1” than the one installed on this computer (%2): install the same model files on both computers.</source>
        <translation>El puesto usa otra versión del modelo «%1» que la instalada en este computador (%2): instale los mismos archivos de modelo en ambos computadores.</translation>
    </message>
    <message>
        <location line="+31" />
        <source>The station's model %1 has errors on this computer: %2</source>
        <translation>El modelo %1 del puesto tiene errores en este computador: %2</translation>
    </message>
</context>
<context>
    <name>studio::DisplayView</name>
    <message>
        <location filename="../ide/studio/centre/display_view.cpp" line="+114" />
        <source>Waiting for station %1…</source>
        <translation>Esperando al puesto %1…</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Station %1 is silent: no state for %2 s.</source>
        <translation>El puesto %1 está en silencio: sin estado desde hace %2 s.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Station %1 has left the centre.</source>
        <translation>El puesto %1 salió del centro.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Waiting for station %1 to announce its model…</source>
        <translation>Esperando que el puesto %1 anuncie su modelo…</translation>
    </message>
</context>
<context>
    <name>studio::DisplayWindow</name>
    <message>
        <location filename="../ide/studio/centre/display_window.cpp" line="+29" />
        <source>This display has no centre key (--centre-key FILE): it cannot check what the stations send, so it shows nothing.</source>
        <translation>Esta pantalla no tiene la clave del centro (--centre-key ARCHIVO): no puede verificar lo que envían los puestos, así que no muestra nada.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>This display's key is station %1's: it cannot check what station %2 sends, so it shows nothing. Give it station %2's key or the centre's key.</source>
        <translation>La clave de esta pantalla es la de la estación %1: no puede verificar lo que envía la estación %2, así que no muestra nada. Dele la clave de la estación %2 o la clave del centro.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>This display cannot join the training centre's network (DDS domain %1): %2</source>
        <translation>Esta pantalla no puede unirse a la red del centro de entrenamiento (dominio DDS %1): %2</translation>
    </message>
    <message>
        <location line="+65" />
        <source>left screen</source>
        <translation>pantalla izquierda</translation>
    </message>
    <message>
        <location line="+0" />
        <source>centre screen</source>
        <translation>pantalla central</translation>
    </message>
    <message>
        <location line="+1" />
        <source>right screen</source>
        <translation>pantalla derecha</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob display: station %1, %2</source>
        <translation>Pantalla Padrob: puesto %1, %2</translation>
    </message>
</context>
<context>
    <name>studio::EditorPanel</name>
    <message>
        <location filename="../ide/studio/editor/editor_panel.cpp" line="+119" />
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Use this model in the 3D view and the simulation</source>
        <translation>Usar este modelo en la vista 3D y en la simulación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Reload</source>
        <translation>Recargar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Read the file again (your unsaved edits stay in Undo)</source>
        <translation>Volver a leer el archivo (sus ediciones sin guardar quedan en Deshacer)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Keep my text</source>
        <translation>Conservar mi texto</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Go on with the text in the editor; saving writes it over the file</source>
        <translation>Seguir con el texto del editor; al guardar se escribe sobre el archivo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>“%1” changed on disk, and the editor has unsaved changes.</source>
        <translation>«%1» cambió en el disco, y el editor tiene cambios sin guardar.</translation>
    </message>
    <message numerus="yes">
        <location line="+179" />
        <source>%1, %n warning(s)</source>
        <comment>the %1 is "%n error(s)"</comment>
        <translation>
            <numerusform>%1, %n advertencia</numerusform>
            <numerusform>%1, %n advertencias</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+20" />
        <source>Not applied: the model has %n error(s). The model applied before stays in use.</source>
        <translation>
            <numerusform>No aplicado: el modelo tiene %n error. El modelo aplicado antes sigue en uso.</numerusform>
            <numerusform>No aplicado: el modelo tiene %n errores. El modelo aplicado antes sigue en uso.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2" />
        <source>Not applied: the model could not be compiled.</source>
        <translation>No aplicado: el modelo no se pudo compilar.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Checking…</source>
        <translation>Revisando…</translation>
    </message>
    <message>
        <location line="-24" />
        <location line="+28" />
        <source>No problems</source>
        <translation>Sin problemas</translation>
    </message>
    <message numerus="yes">
        <location line="-31" />
        <location line="+1" />
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errores</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n advertencia</numerusform>
            <numerusform>%n advertencias</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>studio::FrameBench</name>
    <message>
        <location filename="../ide/studio/app/frame_bench.cpp" line="+196" />
        <source>Cannot read the model %1.</source>
        <translation>No se puede leer el modelo %1.</translation>
    </message>
    <message>
        <location line="+38" />
        <source>The model %1 was not drawn (does it have errors?).</source>
        <translation>El modelo %1 no se dibujó (¿tiene errores?).</translation>
    </message>
    <message>
        <location line="+35" />
        <source>The simulation does not run.</source>
        <translation>La simulación no avanza.</translation>
    </message>
    <message numerus="yes">
        <location line="+21" />
        <source>The %n view(s) do not draw.</source>
        <translation>
            <numerusform>La vista no dibuja.</numerusform>
            <numerusform>Las %n vistas no dibujan.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+175" />
        <source>No model was drawn (does it have errors?).</source>
        <translation>No se dibujó ningún modelo (¿tiene errores?).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Cannot write %1.</source>
        <translation>No se puede escribir %1.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 drawn; the window saved to %2.</source>
        <translation>%1 dibujado; la ventana se guardó en %2.</translation>
    </message>
</context>
<context>
    <name>studio::GettingStarted</name>
    <message>
        <location filename="../ide/studio/app/getting_started.cpp" line="+57" />
        <source>Getting started</source>
        <translation>Primeros pasos</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Run and pause</source>
        <translation>Marcha y pausa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Simulation ▸ Run (%1) starts the machine, Pause (%2) holds it; Reset puts it back at the start.</source>
        <translation>Simulación ▸ Iniciar (%1) pone la máquina en marcha, Pausar (%2) la detiene; Reiniciar la devuelve al inicio.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Keys</source>
        <translation>Teclas</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Click the 3D view, then hold a key to open a valve: the first key of a pair (%1, %2, …) drives one way, the second the other. Simulation ▸ Keyboard Controls lists which drive each pair moves; in Train, the start screen and the attempt name the keys and levers of each stage.</source>
        <translation>Haga clic en la vista 3D y mantenga pulsada una tecla para abrir una válvula: la primera tecla de un par (%1, %2, …) mueve en un sentido y la segunda en el otro. Simulación ▸ Controles de teclado indica qué accionamiento mueve cada par; en Entrenamiento, la pantalla de inicio y el intento indican las teclas y palancas de cada etapa.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Mouse in the 3D view</source>
        <translation>Ratón en la vista 3D</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left drag orbits, middle drag or Shift + left drag pans, the wheel zooms, a double click frames the model.</source>
        <translation>Arrastrar con el botón izquierdo orbita, con el central o Mayús + izquierdo desplaza, la rueda acerca y aleja, y un doble clic encuadra el modelo.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Help ▸ Getting Started shows this again.</source>
        <translation>Ayuda ▸ Primeros pasos lo vuelve a mostrar.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Got it</source>
        <translation>Entendido</translation>
    </message>
</context>
<context>
    <name>studio::HydraulicPanel</name>
    <message>
        <location filename="../ide/studio/sim/hydraulic_panel.cpp" line="+166" />
        <location line="+41" />
        <source>Hydraulics</source>
        <translation>Hidráulica</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Pump %1</source>
        <translation>Bomba %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Pump %1: %2</source>
        <translation>Bomba %1: %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>C %1 %2</source>
        <translation>C %1 %2</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Supply pressure: %1 of %2 MPa</source>
        <translation>Presión de suministro: %1 de %2 MPa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Delivered flow: %1 of %2 L/min</source>
        <translation>Caudal entregado: %1 de %2 L/min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Demand of the open sections: %1 L/min</source>
        <translation>Demanda de las secciones abiertas: %1 L/min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Saturated: the sections want more flow than the pump gives.</source>
        <translation>Saturada: las secciones piden más caudal del que entrega la bomba.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Spool: %1 %</source>
        <translation>Corredera: %1 %</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber A: %1 MPa, flow in %2 L/min</source>
        <translation>Cámara A: %1 MPa, caudal de entrada %2 L/min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber B: %1 MPa, flow in %2 L/min</source>
        <translation>Cámara B: %1 MPa, caudal de entrada %2 L/min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Relief setting: %1 MPa</source>
        <translation>Ajuste de la válvula de alivio: %1 MPa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber A is at the relief setting.</source>
        <translation>La cámara A está en la presión de alivio.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber B is at the relief setting.</source>
        <translation>La cámara B está en la presión de alivio.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber A cavitates.</source>
        <translation>La cámara A cavita.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber B cavitates.</source>
        <translation>La cámara B cavita.</translation>
    </message>
    <message>
        <location line="+54" />
        <source>This model has no fluid-power drives.</source>
        <translation>Este modelo no tiene accionamientos oleohidráulicos.</translation>
    </message>
    <message>
        <location line="+0" />
        <source>No model is running.</source>
        <translation>No hay ningún modelo en marcha.</translation>
    </message>
    <message>
        <location line="+30" />
        <source>supply %1 of %2 MPa</source>
        <translation>suministro %1 de %2 MPa</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+41" />
        <location line="+1" />
        <source>%1 MPa</source>
        <translation>%1 MPa</translation>
    </message>
    <message>
        <location line="-40" />
        <source>flow %1 of %2 L/min, saturated</source>
        <translation>caudal %1 de %2 L/min, saturada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 L/min, saturated</source>
        <translation>%1 L/min, saturada</translation>
    </message>
    <message>
        <location line="+0" />
        <source>saturated</source>
        <translation>saturada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>flow %1 of %2 L/min</source>
        <translation>caudal %1 de %2 L/min</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 L/min</source>
        <translation>%1 L/min</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Spool</source>
        <translation>Corredera</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Chamber A</source>
        <translation>Cámara A</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Chamber B</source>
        <translation>Cámara B</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Valve section</source>
        <translation>Sección de válvula</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 MPa, cavitation</source>
        <translation>%1 MPa, cavitación</translation>
    </message>
    <message>
        <location line="+0" />
        <source>cavitation</source>
        <translation>cavitación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 MPa, relief</source>
        <translation>%1 MPa, alivio</translation>
    </message>
</context>
<context>
    <name>studio::InertiaDialog</name>
    <message>
        <location filename="../ide/studio/dialogs/inertia_dialog.cpp" line="+72" />
        <source>n/a (file: 0)</source>
        <translation>n/d (archivo: 0)</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+4" />
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+155" />
        <source>Inertia calculator</source>
        <translation>Calculadora de inercia</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Body:</source>
        <translation>Cuerpo:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The solids of a body are its graphics (G) with MASS or RHO. Edits in this table only change this calculation: the G lines in the file are not changed. Only the body's B line can be written back, with the button below.</source>
        <translation>Los sólidos de un cuerpo son sus gráficos (G) con MASS o RHO. Lo que se edita en esta tabla solo cambia este cálculo: las líneas G del archivo no se modifican. Solo la línea B del cuerpo se puede escribir en el modelo, con el botón de abajo.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Graphic</source>
        <translation>Gráfico</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Dimensions [m]</source>
        <translation>Dimensiones [m]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>POS [m]</source>
        <translation>POS [m]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>AXIS</source>
        <translation>AXIS</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ROT [axis, °]</source>
        <translation>ROT [eje, °]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Density or mass</source>
        <translation>Densidad o masa</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Solid's mass [kg]</source>
        <translation>Masa del sólido [kg]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH</source>
        <translation>BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM o MESH</translation>
    </message>
    <message>
        <location line="+2" />
        <source>BOX X Y Z; CYL R L; TUBE RO RI L; SPHERE R; CONE R L; ELLIPSOID A B C; PRISM H x1 y1 x2 y2 …; MESH "file" [SCALE s]</source>
        <translation>BOX X Y Z; CYL R L; TUBE RO RI L; SPHERE R; CONE R L; ELLIPSOID A B C; PRISM H x1 y1 x2 y2 …; MESH "archivo" [SCALE s]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>RHO in kg/m³, or MASS in kg</source>
        <translation>RHO en kg/m³, o MASS en kg</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Computed (body axes, about the centre of mass)</source>
        <translation>Calculado (ejes del cuerpo, respecto del centro de masa)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>I = [[Ixx Ixy Ixz] [Ixy Iyy Iyz] [Ixz Iyz Izz]], Ixy = −∫xy dm</source>
        <translation>I = [[Ixx Ixy Ixz] [Ixy Iyy Iyz] [Ixz Iyz Izz]], Ixy = −∫xy dm</translation>
    </message>
    <message>
        <location line="+18" />
        <source>B %1 (no solids)</source>
        <translation>B %1 (sin sólidos)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>B %1  %2 (no solids)</source>
        <translation>B %1  %2 (sin sólidos)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>B %1 (solids: %2)</source>
        <translation>B %1 (sólidos: %2)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>B %1  %2 (solids: %3)</source>
        <translation>B %1  %2 (sólidos: %3)</translation>
    </message>
    <message>
        <location line="-23" />
        <source>Mass:</source>
        <translation>Masa:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centre of mass:</source>
        <translation>Centro de masa:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inertia tensor [kg·m²]:</source>
        <translation>Tensor de inercia [kg·m²]:</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Principal moments:</source>
        <translation>Momentos principales:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Against the file:</source>
        <translation>Respecto del archivo:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>B line</source>
        <translation>Línea B</translation>
    </message>
    <message>
        <location line="+1" />
        <source>In the file:</source>
        <translation>En el archivo:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Computed:</source>
        <translation>Calculada:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Replace B line in editor</source>
        <translation>Reemplazar la línea B en el editor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Writes the computed B line into the editor (one undo step); the G lines stay as they are</source>
        <translation>Escribe la línea B calculada en el editor (se deshace en un paso); las líneas G quedan como están</translation>
    </message>
    <message>
        <location line="+6" />
        <source>B %1</source>
        <translation>B %1</translation>
    </message>
    <message>
        <location line="+14" />
        <source>G %1</source>
        <translation>G %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>line %1</source>
        <translation>línea %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>RHO [kg/m³]</source>
        <translation>RHO [kg/m³]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MASS [kg]</source>
        <translation>MASS [kg]</translation>
    </message>
    <message>
        <location line="+159" />
        <source>Error: %1</source>
        <translation>Error: %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Warning: %1</source>
        <translation>Advertencia: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Error: %1 — %2</source>
        <translation>Error: %1 — %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Warning: %1 — %2</source>
        <translation>Advertencia: %1 — %2</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Body %1 has no solids: give some of its graphics MASS or RHO (e.g. G 1 B %1 BOX 0.2 0.2 0.2 RHO 7850).</source>
        <translation>El cuerpo %1 no tiene sólidos: dé MASS o RHO a alguno de sus gráficos (p. ej., G 1 B %1 BOX 0.2 0.2 0.2 RHO 7850).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The solids have no mass.</source>
        <translation>Los sólidos no tienen masa.</translation>
    </message>
    <message>
        <location line="+37" />
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(%1, %2, %3) m</source>
        <translation>(%1; %2; %3) m</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1, %2, %3 kg·m²</source>
        <translation>%1; %2; %3 kg·m²</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 kg·m² about (%2, %3, %4)</source>
        <translation>%1 kg·m² respecto de (%2; %3; %4)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>m %1, Ixx %2, Iyy %3, Izz %4</source>
        <translation>m %1; Ixx %2; Iyy %3; Izz %4</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the file's B line has no mass</source>
        <translation>la línea B del archivo no tiene masa</translation>
    </message>
</context>
<context>
    <name>studio::InstructorWindow</name>
    <message>
        <location filename="../ide/studio/centre/instructor_window.cpp" line="+269" />
        <source>up</source>
        <translation>en línea</translation>
    </message>
    <message>
        <location line="+0" />
        <source>silent</source>
        <translation>en silencio</translation>
    </message>
    <message>
        <location line="+0" />
        <source>left</source>
        <translation>se fue</translation>
    </message>
    <message>
        <location line="+5" />
        <source>idle</source>
        <translation>inactivo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>running</source>
        <translation>en curso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>paused</source>
        <translation>en pausa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ended</source>
        <translation>terminado</translation>
    </message>
    <message>
        <location line="+4" />
        <source>overload</source>
        <translation>sobrecarga</translation>
    </message>
    <message>
        <location line="+1" />
        <source>near a worker</source>
        <translation>cerca de un trabajador</translation>
    </message>
    <message>
        <location line="+1" />
        <source>near the scene</source>
        <translation>cerca de la escena</translation>
    </message>
    <message>
        <location line="+1" />
        <source>records offline</source>
        <translation>registros fuera de línea</translation>
    </message>
    <message>
        <location line="+1" />
        <source>records kept aside (journal refuses writes)</source>
        <translation>registros guardados aparte (el registro local rechaza escrituras)</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+307" />
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="-295" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1/%2</source>
        <translation>%1/%2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location line="+33" />
        <source>%1 s  %2</source>
        <translation>%1 s  %2</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Padrob instructor</source>
        <translation>Instructor Padrob</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Station</source>
        <translation>Puesto</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Presence</source>
        <translation>Presencia</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Tutorial</source>
        <translation>Tutorial</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Operator</source>
        <translation>Operador</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Score</source>
        <translation>Puntaje</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Goals</source>
        <translation>Objetivos</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Warnings and faults</source>
        <translation>Advertencias y fallas</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Latency</source>
        <translation>Latencia</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start…</source>
        <translation>Iniciar…</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+48" />
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location line="-47" />
        <location line="+48" />
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <location line="-47" />
        <location line="+48" />
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <location line="-47" />
        <location line="+48" />
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <location line="-47" />
        <source>Inject fault…</source>
        <translation>Provocar falla…</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+48" />
        <source>Clear fault</source>
        <translation>Quitar falla</translation>
    </message>
    <message>
        <location line="-47" />
        <source>Events</source>
        <translation>Eventos</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Events of %1 (latest last)</source>
        <translation>Eventos de %1 (el último al final)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Cannot join the training centre's network: %1</source>
        <translation>No se puede unir a la red del centro de entrenamiento: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Centre key %1: commands are signed with it, and what the stations say is checked against it.</source>
        <translation>Clave del centro %1: las órdenes se firman con ella, y lo que dicen los puestos se verifica con ella.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The centre's key cannot be used (%1): what the stations say cannot be checked, so none of it is shown, and no command can be sent.</source>
        <translation>La clave del centro no se puede usar (%1): lo que dicen los puestos no se puede verificar, así que no se muestra nada de ello, y no se pueden enviar órdenes.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Without the centre's key (--centre-key FILE) what the stations say cannot be checked, so none of it is shown, and no command can be sent.</source>
        <translation>Sin la clave del centro (--centre-key ARCHIVO) lo que dicen los puestos no se puede verificar, así que no se muestra nada de ello, y no se pueden enviar órdenes.</translation>
    </message>
    <message>
        <location line="+43" />
        <source>the station has already taken this very command (a replay).</source>
        <translation>el puesto ya recibió esta misma orden (una repetición).</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a field of the command is longer than the centre allows.</source>
        <translation>un campo de la orden es más largo de lo que el centro permite.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station has taken too many commands in the last 30 seconds; try again shortly.</source>
        <translation>el puesto recibió demasiadas órdenes en los últimos 30 segundos; intente de nuevo en un momento.</translation>
    </message>
    <message>
        <location line="-37" />
        <source>Not connected to the training centre's network.</source>
        <translation>Sin conexión a la red del centro de entrenamiento.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Commands need the centre's key: start padrob-studio with --centre-key FILE.</source>
        <translation>Las órdenes necesitan la clave del centro: inicie padrob-studio con --centre-key ARCHIVO.</translation>
    </message>
    <message>
        <location line="+19" />
        <location line="+89" />
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <location line="-84" />
        <source>Inject fault</source>
        <translation>Provocar falla</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the command was not signed with the key this station has.</source>
        <translation>la orden no se firmó con la clave que tiene este puesto.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the command was too old when it arrived: check that the computers' clocks agree.</source>
        <translation>la orden llegó demasiado tarde: revise que los relojes de los computadores coincidan.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the station has no centre key and takes no commands.</source>
        <translation>el puesto no tiene clave del centro y no acepta órdenes.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no attempt is running on the station.</source>
        <translation>no hay un intento en curso en el puesto.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the attempt is not paused.</source>
        <translation>el intento no está en pausa.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station does not have that tutorial.</source>
        <translation>el puesto no tiene ese tutorial.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station does not know that fault.</source>
        <translation>el puesto no conoce esa falla.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station does not know that command.</source>
        <translation>el puesto no conoce esa orden.</translation>
    </message>
    <message>
        <location line="+21" />
        <source>%1 on %2</source>
        <translation>%1 en %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: sent, waiting for the station…</source>
        <translation>%1: enviado, esperando al puesto…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: could not be sent.</source>
        <translation>%1: no se pudo enviar.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: could not be sent (%2).</source>
        <translation>%1: no se pudo enviar (%2).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: done.</source>
        <translation>%1: hecho.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: refused, %2</source>
        <translation>%1: rechazado, %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: no reply from the station in 5 s.</source>
        <translation>%1: el puesto no respondió en 5 s.</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Start a tutorial on %1</source>
        <translation>Iniciar un tutorial en %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>guest</source>
        <translation>invitado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tutorial:</source>
        <translation>Tutorial:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Operator code:</source>
        <translation>Código del operador:</translation>
    </message>
    <message>
        <location line="+19" />
        <source>Inject a fault on %1</source>
        <translation>Provocar una falla en %1</translation>
    </message>
    <message>
        <location line="+30" />
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Fault:</source>
        <translation>Falla:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Drive:</source>
        <translation>Accionamiento:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Valve opening (−1 … 1):</source>
        <translation>Apertura de la válvula (−1 … 1):</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Where the worker walks to (x, y, z):</source>
        <translation>Hacia dónde camina el trabajador (x, y, z):</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Inject</source>
        <translation>Provocar</translation>
    </message>
</context>
<context>
    <name>studio::JointSliders</name>
    <message>
        <location filename="../ide/studio/tree/joint_sliders.cpp" line="+77" />
        <source>Reset pose</source>
        <translation>Restablecer postura</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back to the model's initial coordinates</source>
        <translation>Volver a las coordenadas iniciales del modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>No model</source>
        <translation>Sin modelo</translation>
    </message>
    <message>
        <location line="+5" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>C %1  %2</source>
        <translation>C %1  %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1, limits %2</source>
        <translation>%1; límites %2</translation>
    </message>
    <message>
        <location line="+6" />
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location line="+0" />
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location line="-13" />
        <source>The model has no degrees of freedom to pose.</source>
        <translation>El modelo no tiene grados de libertad que mover.</translation>
    </message>
    <message>
        <location line="+232" />
        <source>C %1 cannot reach the length %2: kept the last pose.</source>
        <translation>C %1 no puede alcanzar el largo %2: se mantiene la última postura.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>The loops cannot close with C %1 at %2: the pose stops at %3, the last one that closes.</source>
        <translation>Los lazos no pueden cerrarse con C %1 en %2: la postura se detiene en %3, la última que cierra.</translation>
    </message>
</context>
<context>
    <name>studio::JointText</name>
    <message>
        <location filename="../ide/studio/tree/joint_text.cpp" line="+27" />
        <location line="+31" />
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <location line="-30" />
        <location line="+31" />
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location line="-27" />
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location line="+0" />
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+14" />
        <source>revolute</source>
        <translation>rotacional</translation>
    </message>
    <message>
        <location line="+1" />
        <source>pivoted actuator</source>
        <translation>actuador pivotado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>prismatic</source>
        <translation>prismática</translation>
    </message>
    <message>
        <location line="+1" />
        <source>free body</source>
        <translation>cuerpo libre</translation>
    </message>
    <message>
        <location line="+5" />
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location line="+0" />
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>≤ %1</source>
        <translation>≤ %1</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+29" />
        <source>unlimited</source>
        <translation>sin límite</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 MN·m</source>
        <translation>%1 MN·m</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 MN</source>
        <translation>%1 MN</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 kN·m</source>
        <translation>%1 kN·m</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 kN</source>
        <translation>%1 kN</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 N·m</source>
        <translation>%1 N·m</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>+%1/-%2 %3</source>
        <translation>+%1/-%2 %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>+%1/-%2</source>
        <translation>+%1/-%2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>hydraulic %1, relief %2</source>
        <translation>hidráulico %1; alivio %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>hydraulic %1</source>
        <translation>hidráulico %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>motor T0 %1, W0 %2 rad/s</source>
        <translation>motor T0 %1; W0 %2 rad/s</translation>
    </message>
    <message>
        <location line="+3" />
        <source>pneumatic %1</source>
        <translation>neumático %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>servo KP %1, KI %2, KD %3</source>
        <translation>servo KP %1; KI %2; KD %3</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1, FMAX %2</source>
        <translation>%1; FMAX %2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>massless</source>
        <translation>sin masa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
</context>
<context>
    <name>studio::KeyboardInput</name>
    <message>
        <location filename="../ide/studio/sim/keyboard_input.cpp" line="+103" />
        <source>%1 — C %2</source>
        <translation>%1 — C %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 — C %2 %3</source>
        <translation>%1 — C %2 %3</translation>
    </message>
</context>
<context>
    <name>studio::MainWindow</name>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="+155" />
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+240" />
        <location line="+2" />
        <source>Model</source>
        <translation>Modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Joints</source>
        <translation>Articulaciones</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Editor</source>
        <translation>Editor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Plots</source>
        <translation>Gráficos</translation>
    </message>
    <message>
        <location line="-5" />
        <source>Train</source>
        <translation>Entrenamiento</translation>
    </message>
    <message>
        <location line="-1" />
        <source>Workspaces</source>
        <translation>Espacios de trabajo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Station</source>
        <translation>Puesto</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="+201" />
        <source>Leave Trainer Mode</source>
        <translation>Salir del modo quiosco</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Trainer's PIN:</source>
        <translation>PIN del instructor:</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+16" />
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;New</source>
        <translation>&amp;Nuevo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Open…</source>
        <translation>&amp;Abrir…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Save</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save &amp;As…</source>
        <translation>Guardar &amp;como…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Recent Files</source>
        <translation>Archivos &amp;recientes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Examples</source>
        <translation>&amp;Ejemplos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Undo</source>
        <translation>&amp;Deshacer</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Redo</source>
        <translation>&amp;Rehacer</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Apply Model</source>
        <translation>&amp;Aplicar modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Inertia Calculator…</source>
        <translation>Calculadora de &amp;inercia…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;Schematic</source>
        <translation>&amp;Esquemático</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Dressed</source>
        <translation>Con &amp;geometría</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Both</source>
        <translation>&amp;Ambos</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;Camera</source>
        <translation>&amp;Cámara</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Fit All</source>
        <translation>Encuadrar &amp;todo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>S&amp;cene</source>
        <translation>E&amp;scena</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Load…</source>
        <translation>&amp;Cargar…</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="+43" />
        <location filename="../ide/studio/app/main_window_menus.cpp" line="-175" />
        <source>Load Scene</source>
        <translation>Cargar escena</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+176" />
        <source>&amp;None</source>
        <translation>&amp;Ninguna</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Body &amp;Frames</source>
        <translation>E&amp;jes de los cuerpos</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;Screens</source>
        <translation>&amp;Pantallas</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>%n Screen(s)</source>
        <translation>
            <numerusform>%n pantalla</numerusform>
            <numerusform>%n pantallas</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1" />
        <source>Three &amp;Windows (three monitors)</source>
        <translation>Tres &amp;ventanas (tres monitores)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Simulation</source>
        <translation>&amp;Simulación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Run</source>
        <translation>&amp;Iniciar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Pause</source>
        <translation>Pa&amp;usar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Step</source>
        <translation>&amp;Avanzar un paso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>R&amp;eset</source>
        <translation>&amp;Reiniciar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>S&amp;peed</source>
        <translation>&amp;Velocidad</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Keyboard Controls…</source>
        <translation>&amp;Controles de teclado…</translation>
    </message>
    <message>
        <location line="+17" />
        <source>&amp;Getting Started</source>
        <translation>&amp;Primeros pasos</translation>
    </message>
    <message>
        <location line="+22" />
        <source>+</source>
        <translation>+</translation>
    </message>
    <message>
        <location line="+0" />
        <source>−</source>
        <translation>−</translation>
    </message>
    <message>
        <location line="+4" />
        <source>turns +</source>
        <comment>a revolute joint's angle grows</comment>
        <translation>gira +</translation>
    </message>
    <message>
        <location line="+1" />
        <source>turns −</source>
        <comment>a revolute joint's angle shrinks</comment>
        <translation>gira −</translation>
    </message>
    <message>
        <location line="+3" />
        <source>cylinder out</source>
        <comment>a T 1 joint's actuator lengthens</comment>
        <translation>sale el cilindro</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cylinder in</source>
        <comment>a T 1 joint's actuator shortens</comment>
        <translation>entra el cilindro</translation>
    </message>
    <message>
        <location line="+3" />
        <source>slides +</source>
        <comment>a prismatic joint's displacement grows</comment>
        <translation>desliza +</translation>
    </message>
    <message>
        <location line="+1" />
        <source>slides −</source>
        <comment>a prismatic joint's displacement shrinks</comment>
        <translation>desliza −</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: %2 · %3: %4</source>
        <comment>each key of a pair and which way it moves the drive</comment>
        <translation>%1: %2 · %3: %4</translation>
    </message>
    <message>
        <location line="+12" />
        <location line="+10" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Left drag</source>
        <translation>Arrastrar con el botón izquierdo</translation>
    </message>
    <message>
        <location line="+0" />
        <source>orbits around the model</source>
        <translation>gira alrededor del modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Middle drag, or Shift + left drag</source>
        <translation>Arrastrar con el botón central, o Mayús + botón izquierdo</translation>
    </message>
    <message>
        <location line="+0" />
        <source>pans</source>
        <translation>desplaza la vista</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Wheel</source>
        <translation>Rueda</translation>
    </message>
    <message>
        <location line="+0" />
        <source>zooms towards the cursor</source>
        <translation>acerca o aleja hacia el cursor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Double click</source>
        <translation>Doble clic</translation>
    </message>
    <message>
        <location line="+0" />
        <source>frames the whole model</source>
        <translation>encuadra todo el modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ctrl + left drag on a body</source>
        <translation>Ctrl + arrastrar con el botón izquierdo sobre un cuerpo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>picks the body and pushes it while the simulation runs (a spring pulls the point you grabbed toward the cursor); release to let go</source>
        <translation>toma el cuerpo y lo empuja mientras corre la simulación (un resorte tira del punto tomado hacia el cursor); suelte para liberarlo</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Keyboard Controls</source>
        <translation>Controles de teclado</translation>
    </message>
    <message>
        <location line="+2" />
        <source>With the 3D view focused, hold a key to open a valve:</source>
        <translation>Con la vista 3D activa, mantenga presionada una tecla para abrir una válvula:</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Mouse in the 3D view:</source>
        <translation>Mouse en la vista 3D:</translation>
    </message>
    <message>
        <location line="-98" />
        <source>&amp;Help</source>
        <translation>Ay&amp;uda</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Model &amp;Language Reference</source>
        <translation>&amp;Referencia del lenguaje de modelos</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;About Padrob Studio</source>
        <translation>&amp;Acerca de Padrob Studio</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="-16" />
        <location line="+79" />
        <source>Open Model</source>
        <translation>Abrir modelo</translation>
    </message>
    <message>
        <location line="-79" />
        <source>Cannot open %1:
%2</source>
        <translation>No se puede abrir %1:
%2</translation>
    </message>
    <message>
        <location line="+79" />
        <location filename="../ide/studio/app/main_window_menus.cpp" line="-208" />
        <source>Padrob models (*.pad);;All files (*)</source>
        <translation>Modelos Padrob (*.pad);;Todos los archivos (*)</translation>
    </message>
    <message numerus="yes">
        <location line="-284" />
        <source>%n attempt(s) kept while the trainee records could not be written were added to them.</source>
        <translation>
            <numerusform>Se agregó a los registros de los aprendices %n intento guardado mientras no se podían escribir.</numerusform>
            <numerusform>Se agregaron a los registros de los aprendices %n intentos guardados mientras no se podían escribir.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2" />
        <source>The trainee records cannot be opened: %1</source>
        <translation>No se pueden abrir los registros de los aprendices: %1</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+139" />
        <source>Hydraulics</source>
        <translation>Hidráulica</translation>
    </message>
    <message>
        <location line="+38" />
        <source>&amp;Contacts</source>
        <translation>&amp;Contactos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Show where solids touch (models with CONTACT): a red disc at each contact point, its force as an orange arrow</source>
        <translation>Muestra dónde se tocan los sólidos (modelos con CONTACT): un disco rojo en cada punto de contacto y su fuerza como una flecha naranja</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Se&amp;ttings</source>
        <translation>&amp;Configuración</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <location line="+1" />
        <source>L&amp;ighting</source>
        <translation>I&amp;luminación</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;Automatic: at the vertices on a software OpenGL, else at every pixel</source>
        <translation>&amp;Automática: en los vértices con un OpenGL por software; si no, en cada píxel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>At every &amp;pixel (finer)</source>
        <translation>En cada &amp;píxel (más fina)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>At the &amp;vertices (faster)</source>
        <translation>En los &amp;vértices (más rápida)</translation>
    </message>
    <message>
        <location line="+70" />
        <source>%1 (%2)</source>
        <comment>a drive and its bank</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>C %1 %2</source>
        <translation>C %1 %2</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Shortcuts (none of them opens a valve):</source>
        <translation>Atajos (ninguno abre una válvula):</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="+220" />
        <source>%1

The 3D view goes on without this scene.</source>
        <translation>%1

La vista 3D continúa sin esta escena.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Scene: %1</source>
        <translation>Escena: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Scene: %1. %2</source>
        <translation>Escena: %1. %2</translation>
    </message>
    <message>
        <location line="+22" />
        <source>The scene used last is not drawn: %1</source>
        <translation>La última escena usada no se dibuja: %1</translation>
    </message>
    <message>
        <location line="+35" />
        <location line="+14" />
        <source>Save Model</source>
        <translation>Guardar modelo</translation>
    </message>
    <message>
        <location line="-14" />
        <source>The model was not saved:
%1

Use Save As to choose another place.</source>
        <translation>El modelo no se guardó:
%1

Use Guardar como para elegir otro lugar.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Save Model As</source>
        <translation>Guardar modelo como</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Padrob models (*.pad)</source>
        <translation>Modelos Padrob (*.pad)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The model was not saved:
%1</source>
        <translation>El modelo no se guardó:
%1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Unsaved Changes</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The model has unsaved changes. Save them?</source>
        <translation>El modelo tiene cambios sin guardar. ¿Guardarlos?</translation>
    </message>
    <message>
        <location line="+33" />
        <source>Untitled</source>
        <translation>Sin título</translation>
    </message>
    <message>
        <location line="+8" />
        <source>an untitled model</source>
        <translation>un modelo sin título</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Recover Unsaved Changes</source>
        <translation>Recuperar cambios sin guardar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob Studio was closed with unsaved changes to %1 (recovery copy of %2). Restore them?</source>
        <translation>Padrob Studio se cerró con cambios sin guardar en %1 (copia de recuperación del %2). ¿Restaurarlos?</translation>
    </message>
    <message>
        <location line="+91" />
        <source>real time ×%1, %2 µs/step</source>
        <translation>tiempo real ×%1; %2 µs/paso</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_reload.cpp" line="+52" />
        <source>%1 was deleted or moved on disk; the text in the editor is kept — save it to write it again.</source>
        <translation>%1 se eliminó o se movió en el disco; el texto del editor se conserva: guárdelo para escribirlo de nuevo.</translation>
    </message>
    <message>
        <location line="+31" />
        <source>%1 changed on disk and was reloaded; the pose is kept.</source>
        <translation>%1 cambió en el disco y se volvió a cargar; se conserva la postura.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 changed on disk and was reloaded; its joints changed, so it starts from the initial pose.</source>
        <translation>%1 cambió en el disco y se volvió a cargar; sus articulaciones cambiaron, así que parte de la postura inicial.</translation>
    </message>
    <message>
        <location line="+15" />
        <source>The editor has changes that are not applied: the 3D view, the tree and the plots show the model applied before. Apply (Ctrl+Return) to use them, or Revert.</source>
        <translation>El editor tiene cambios no aplicados: la vista 3D, el árbol y los gráficos muestran el modelo aplicado antes. Aplíquelos (Ctrl+Intro) para usarlos, o reviértalos.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Revert</source>
        <translation>Revertir</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Put the applied model's text back in the editor (Undo brings the edits back)</source>
        <translation>Devolver al editor el texto del modelo aplicado (Deshacer recupera las ediciones)</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="-58" />
        <source>The scene's solids cannot be taken into the model's contacts (a shape that cannot serve): the model runs without touching them</source>
        <translation>Los sólidos de la escena no pueden incorporarse a los contactos del modelo (una forma que no sirve): el modelo funciona sin tocarlos</translation>
    </message>
    <message numerus="yes">
        <location line="+15" />
        <source>Model applied: %n bodies</source>
        <translation>
            <numerusform>Modelo aplicado: %n cuerpo</numerusform>
            <numerusform>Modelo aplicado: %n cuerpos</numerusform>
        </translation>
    </message>
    <message>
        <location line="+40" />
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <location line="+6" />
        <source>paused</source>
        <translation>en pausa</translation>
    </message>
    <message>
        <location line="+5" />
        <source>frame %1 ms</source>
        <translation>cuadro %1 ms</translation>
    </message>
    <message>
        <location line="+52" />
        <source>Simulation Stopped</source>
        <translation>Simulación detenida</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1

The simulation is paused at the last good state; the editor stays usable. Reset to start again.</source>
        <translation>%1

La simulación quedó en pausa en el último estado válido; el editor sigue disponible. Reinicie para comenzar de nuevo.</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+12" />
        <source>Model Language Reference</source>
        <translation>Referencia del lenguaje de modelos</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The reference (docs/model-language.md) was not found at %1.</source>
        <translation>La referencia (docs/model-language.md) no se encontró en %1.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>About Padrob Studio</source>
        <translation>Acerca de Padrob Studio</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&lt;h3&gt;Padrob Studio %1&lt;/h3&gt;&lt;p&gt;Real-time training simulators of heavy machines, built from a model file: bodies, joints, hydraulic drives, forces and graphics.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Padrob Studio %1&lt;/h3&gt;&lt;p&gt;Simuladores de entrenamiento en tiempo real para maquinaria pesada, construidos a partir de un archivo de modelo: cuerpos, articulaciones, accionamientos hidráulicos, fuerzas y gráficos.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_tools.cpp" line="+37" />
        <location line="+137" />
        <source>Record Video</source>
        <translation>Grabar video</translation>
    </message>
    <message>
        <location line="-76" />
        <source>Video saved: %1 (%2 s)</source>
        <translation>Video guardado: %1 (%2 s)</translation>
    </message>
    <message>
        <location line="+15" />
        <source>%1 (%2)</source>
        <comment>an action and its shortcut</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Speed:</source>
        <translation>Velocidad:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Simulated seconds per second of the wall clock (Simulation ▸ Speed)</source>
        <translation>Segundos simulados por segundo de reloj (Simulación ▸ Velocidad)</translation>
    </message>
    <message>
        <location line="+58" />
        <source>Videos (*.mp4 *.mkv *.mov)</source>
        <translation>Videos (*.mp4 *.mkv *.mov)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Stop &amp;Recording</source>
        <translation>Detener la &amp;grabación</translation>
    </message>
    <message>
        <location line="+0" />
        <source>&amp;Record Video…</source>
        <translation>&amp;Grabar video…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stop recording the 3D view</source>
        <translation>Dejar de grabar la vista 3D</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Record a video of the 3D view (ffmpeg)</source>
        <translation>Grabar un video de la vista 3D (ffmpeg)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>● REC %1:%2</source>
        <translation>● GRAB %1:%2</translation>
    </message>
</context>
<context>
    <name>studio::MappingTable</name>
    <message>
        <location filename="../ide/studio/station/mapping_table.cpp" line="+52" />
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The button's number on that device (as the channel lamps show it)</source>
        <translation>El número del botón en ese dispositivo (como lo muestran las luces de los canales)</translation>
    </message>
    <message>
        <location line="+104" />
        <location line="+15" />
        <source>Bank</source>
        <translation>Banco</translation>
    </message>
    <message>
        <location line="-15" />
        <source>Device</source>
        <translation>Dispositivo</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Axis</source>
        <translation>Eje</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Drive</source>
        <translation>Accionamiento</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Gain</source>
        <translation>Ganancia</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Sign</source>
        <translation>Signo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Live</source>
        <translation>En vivo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>A device id, or a kind (gamepad, joystick, serial, comedi, keyboard): the first connected device of that kind</source>
        <translation>El id de un dispositivo, o un tipo (gamepad, joystick, serial, comedi, keyboard): el primer dispositivo conectado de ese tipo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Command = gain × sign × calibrated value (0 … 10)</source>
        <translation>Comando = ganancia × signo × valor calibrado (0 … 10)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>What the mapping gives its drive now; after a profile change, a bank switch or a reconnection it waits until the lever is back at the centre</source>
        <translation>Lo que la asignación entrega ahora a su accionamiento; después de un cambio de perfil, un cambio de banco o una reconexión espera hasta que la palanca vuelva al centro</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Add mapping</source>
        <translation>Agregar asignación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A new row in the selected row's bank</source>
        <translation>Una fila nueva en el banco de la fila seleccionada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove mapping</source>
        <translation>Quitar asignación</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Banks</source>
        <translation>Bancos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A device with fewer axes than the machine has drives switches between banks of mappings with its buttons; the “Always” mappings act in every bank.</source>
        <translation>Un dispositivo con menos ejes que accionamientos tiene la máquina cambia entre bancos de asignaciones con sus botones; las asignaciones “Siempre” actúan en todos los bancos.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Selected by device</source>
        <translation>Seleccionado por dispositivo</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Button</source>
        <translation>Botón</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Add bank</source>
        <translation>Agregar banco</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Rename bank</source>
        <translation>Renombrar banco</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove bank</source>
        <translation>Quitar banco</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next bank:</source>
        <translation>Banco siguiente:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The device whose button steps to the next bank</source>
        <translation>El dispositivo cuyo botón pasa al banco siguiente</translation>
    </message>
    <message>
        <location line="+93" />
        <source>Always</source>
        <translation>Siempre</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+425" />
        <source>Bank %1</source>
        <translation>Banco %1</translation>
    </message>
    <message>
        <location line="-415" />
        <source>The first connected device of this kind</source>
        <translation>El primer dispositivo conectado de este tipo</translation>
    </message>
    <message>
        <location line="+19" />
        <location line="+8" />
        <source>Axis %1</source>
        <translation>Eje %1</translation>
    </message>
    <message>
        <location line="+27" />
        <source>C %1 (not in this model)</source>
        <translation>C %1 (no está en este modelo)</translation>
    </message>
    <message>
        <location line="+35" />
        <source>−: the lever drives the valve the other way</source>
        <translation>−: la palanca acciona la válvula en el otro sentido</translation>
    </message>
    <message numerus="yes">
        <location line="+83" />
        <source>%n more button(s) of the profile also select this bank</source>
        <translation>
            <numerusform>%n botón más del perfil también selecciona este banco</numerusform>
            <numerusform>%n botones más del perfil también seleccionan este banco</numerusform>
        </translation>
    </message>
    <message>
        <location line="+166" />
        <source>ignored</source>
        <translation>ignorada</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The model has no such drive, or the gain or sign is not valid</source>
        <translation>El modelo no tiene ese accionamiento, o la ganancia o el signo no son válidos</translation>
    </message>
    <message>
        <location line="+3" />
        <source>no %1 found</source>
        <translation>no se encontró %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>device not connected</source>
        <translation>dispositivo no conectado</translation>
    </message>
    <message>
        <location line="+3" />
        <source>bank not active</source>
        <translation>banco no activo</translation>
    </message>
    <message>
        <location line="+3" />
        <source>waiting for centre</source>
        <translation>esperando el centro</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Bring the lever back to the centre to take over this drive</source>
        <translation>Devuelva la palanca al centro para tomar el control de este accionamiento</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Contribution to the drive's command now (device %1)</source>
        <translation>Aporte actual al comando del accionamiento (dispositivo %1)</translation>
    </message>
    <message numerus="yes">
        <location line="+79" />
        <source>Remove the bank “%1” and its %n mapping(s)?</source>
        <translation>
            <numerusform>¿Quitar el banco “%1” y su %n asignación?</numerusform>
            <numerusform>¿Quitar el banco “%1” y sus %n asignaciones?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>studio::ModelDocument</name>
    <message>
        <location filename="../ide/studio/editor/model_document.cpp" line="+111" />
        <location line="+306" />
        <source>Untitled</source>
        <translation>Sin título</translation>
    </message>
    <message>
        <location line="-291" />
        <source>The file “%1” does not exist.</source>
        <translation>El archivo “%1” no existe.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>“%1” is a folder, not a model file.</source>
        <translation>“%1” es una carpeta, no un archivo de modelo.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>“%1” is not a regular file.</source>
        <translation>“%1” no es un archivo normal.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>“%1” is too large for a model file (%2 MB; at most %3 MB).</source>
        <translation>“%1” es demasiado grande para un archivo de modelo (%2 MB; máximo %3 MB).</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+2" />
        <source>Cannot read “%1”: %2.</source>
        <translation>No se puede leer “%1”: %2.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>“%1” is not a text file (it contains binary data).</source>
        <translation>“%1” no es un archivo de texto (contiene datos binarios).</translation>
    </message>
    <message>
        <location line="+26" />
        <source>Cannot save “%1”: it is a folder.</source>
        <translation>No se puede guardar “%1”: es una carpeta.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cannot save “%1”: the folder “%2” does not exist.</source>
        <translation>No se puede guardar “%1”: la carpeta “%2” no existe.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cannot save “%1”: the file is read-only.</source>
        <translation>No se puede guardar “%1”: el archivo es de solo lectura.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cannot save “%1”: the folder “%2” is not writable (permission denied). Save it somewhere else.</source>
        <translation>No se puede guardar “%1”: no hay permiso para escribir en la carpeta “%2”. Guárdelo en otro lugar.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Cannot save “%1”: %2.</source>
        <translation>No se puede guardar “%1”: %2.</translation>
    </message>
    <message>
        <location line="+41" />
        <source>The model has no file to reload.</source>
        <translation>El modelo no tiene un archivo que volver a cargar.</translation>
    </message>
    <message>
        <location line="+20" />
        <source>The model has no file name yet: use Save As.</source>
        <translation>El modelo aún no tiene nombre de archivo: use Guardar como.</translation>
    </message>
    <message>
        <location line="+109" />
        <source>cannot create the folder</source>
        <translation>no se puede crear la carpeta</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Cannot write the recovery copy “%1”: %2.</source>
        <translation>No se puede escribir la copia de recuperación “%1”: %2.</translation>
    </message>
    <message>
        <location line="+75" />
        <source>Cannot read the recovery copy “%1”: %2.</source>
        <translation>No se puede leer la copia de recuperación “%1”: %2.</translation>
    </message>
</context>
<context>
    <name>studio::ModelTree</name>
    <message>
        <location filename="../ide/studio/tree/model_tree.cpp" line="+48" />
        <source>Element</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Role</source>
        <translation>Rol</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Mass / limits</source>
        <translation>Masa / límites</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Drive</source>
        <translation>Accionamiento</translation>
    </message>
    <message>
        <location line="+39" />
        <source>loop closure</source>
        <translation>cierre de lazo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>dependent</source>
        <translation>dependiente</translation>
    </message>
    <message>
        <location line="+1" />
        <source>independent</source>
        <translation>independiente</translation>
    </message>
    <message>
        <location line="+2" />
        <source>passive</source>
        <translation>pasiva</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+70" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="-70" />
        <source>C %1  %2</source>
        <translation>C %1  %2</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+29" />
        <location line="+1" />
        <source>ground</source>
        <translation>tierra</translation>
    </message>
    <message>
        <location line="-29" />
        <source>B %1 %2</source>
        <translation>B %1 %2</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+37" />
        <source>B %1</source>
        <translation>B %1</translation>
    </message>
    <message>
        <location line="-34" />
        <source>Joint %1 (%2), line %3</source>
        <translation>Articulación %1 (%2), línea %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>between %1 and %2</source>
        <translation>entre %1 y %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>limits: %1</source>
        <translation>límites: %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>drive: %1</source>
        <translation>accionamiento: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>initial coordinate: %1</source>
        <translation>coordenada inicial: %1</translation>
    </message>
    <message>
        <location line="+36" />
        <source>Body %1, line %2</source>
        <translation>Cuerpo %1, línea %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source>mass: %1</source>
        <translation>masa: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Ixx Iyy Izz: %1 %2 %3 kg·m²</source>
        <translation>Ixx Iyy Izz: %1 %2 %3 kg·m²</translation>
    </message>
    <message>
        <location line="+4" />
        <source>moved by joint C %1</source>
        <translation>movido por la articulación C %1</translation>
    </message>
    <message>
        <location line="-24" />
        <source>Bodies (%1)</source>
        <translation>Cuerpos (%1)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>B 0  %1</source>
        <translation>B 0  %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>fixed</source>
        <translation>fijo</translation>
    </message>
    <message>
        <location line="+8" />
        <source>B %1  %2</source>
        <translation>B %1  %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>body</source>
        <translation>cuerpo</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Joints (%1)</source>
        <translation>Articulaciones (%1)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Chains (%1)</source>
        <translation>Cadenas (%1)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Chain %1:  %2</source>
        <translation>Cadena %1:  %2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Loop closures (%1)</source>
        <translation>Cierres de lazo (%1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>none: the joints form an open tree</source>
        <translation>ninguno: las articulaciones forman un árbol abierto</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Coordinates (degrees of freedom: %1)</source>
        <translation>Coordenadas (grados de libertad: %1)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>initially %1</source>
        <translation>inicialmente %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Independent (%1)</source>
        <translation>Independientes (%1)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Dependent (%1)</source>
        <translation>Dependientes (%1)</translation>
    </message>
</context>
<context>
    <name>studio::OverrunMeter</name>
    <message>
        <location filename="../ide/studio/sim/overrun_meter.cpp" line="+29" />
        <source>%1 % of steps late</source>
        <translation>%1 % de pasos atrasados</translation>
    </message>
    <message numerus="yes">
        <location line="+5" />
        <source>An overrun is a solver step that took longer to compute than the real time it simulates: the simulation falls behind the wall clock. The share shown is that of the last %1 s (%n overrun(s) since Run).
A few are harmless. If the share stays high, this computer cannot keep up: lower the speed (Simulation ▸ Speed), close other programs, choose Settings ▸ Lighting ▸ At the vertices, or simplify the model.</source>
        <translation><numerusform>Un paso atrasado es un paso del solver que tardó más en calcularse que el tiempo real que simula: la simulación se queda atrás del reloj. La proporción mostrada es la de los últimos %1 s (%n paso atrasado desde Ejecutar).
Algunos no hacen daño. Si la proporción sigue alta, este ordenador no da abasto: baje la velocidad (Simulación ▸ Velocidad), cierre otros programas, elija Configuración ▸ Iluminación ▸ En los vértices o simplifique el modelo.</numerusform><numerusform>Un paso atrasado es un paso del solver que tardó más en calcularse que el tiempo real que simula: la simulación se queda atrás del reloj. La proporción mostrada es la de los últimos %1 s (%n pasos atrasados desde Ejecutar).
Algunos no hacen daño. Si la proporción sigue alta, este ordenador no da abasto: baje la velocidad (Simulación ▸ Velocidad), cierre otros programas, elija Configuración ▸ Iluminación ▸ En los vértices o simplifique el modelo.</numerusform></translation>
    </message>
</context>
<context>
    <name>studio::PinDialog</name>
    <message>
        <location filename="../ide/studio/train/pin_dialog.cpp" line="+37" />
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location line="+33" />
        <source>That is not the trainer's PIN. Try again.</source>
        <translation>Ese no es el PIN del instructor. Inténtelo de nuevo.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Type the trainer's PIN.</source>
        <translation>Escriba el PIN del instructor.</translation>
    </message>
    <message numerus="yes">
        <location line="+8" />
        <source>Too many wrong PINs: wait %n s.</source>
        <translation><numerusform>Demasiados PIN equivocados: espere %n s.</numerusform><numerusform>Demasiados PIN equivocados: espere %n s.</numerusform></translation>
    </message>
</context>
<context>
    <name>studio::PlotPanel</name>
    <message>
        <location filename="../ide/studio/plots/plot_panel.cpp" line="+150" />
        <source>Clear</source>
        <translation>Limpiar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Forget the samples plotted so far</source>
        <translation>Descartar las muestras graficadas hasta ahora</translation>
    </message>
    <message>
        <location line="+1" />
        <source>CSV…</source>
        <translation>CSV…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Export time and the ticked signals as CSV</source>
        <translation>Exportar el tiempo y las señales marcadas como CSV</translation>
    </message>
    <message>
        <location line="+1" />
        <source>PNG…</source>
        <translation>PNG…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save the charts as a PNG image</source>
        <translation>Guardar los gráficos como imagen PNG</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tick signals in the list to plot them against time.</source>
        <translation>Marque señales en la lista para graficarlas en función del tiempo.</translation>
    </message>
    <message>
        <location line="+16" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>C %1 %2</source>
        <translation>C %1 %2</translation>
    </message>
    <message>
        <location line="-8" />
        <source>F drive</source>
        <translation>F accionamiento</translation>
    </message>
    <message>
        <location line="-16" />
        <source>Tick the signals to plot; each unit gets its own chart, or choose beside a ticked signal a numbered chart to overlay signals of any units.</source>
        <translation>Marque las señales que quiere graficar; cada unidad tiene su propio gráfico, o elija junto a una señal marcada un gráfico numerado para superponer señales de cualquier unidad.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>mechanical energy [J]</source>
        <translation>energía mecánica [J]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>largest contact force [kN]</source>
        <translation>mayor fuerza de contacto [kN]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 %2 [%3]</source>
        <comment>a signal: the joint, the quantity's symbol, its unit</comment>
        <translation>%1 %2 [%3]</translation>
    </message>
    <message>
        <location line="+6" />
        <source>pump %1</source>
        <translation>bomba %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>pump %1 %2</source>
        <translation>bomba %1 %2</translation>
    </message>
    <message>
        <location line="+284" />
        <source>The chart this signal is drawn in: its unit's, or a numbered one shared by signals of any units</source>
        <translation>El gráfico en que se dibuja esta señal: el de su unidad, o uno numerado que comparten señales de cualquier unidad</translation>
    </message>
    <message>
        <location line="+2" />
        <source>by unit</source>
        <translation>por unidad</translation>
    </message>
    <message>
        <location line="+1" />
        <source>chart %1</source>
        <translation>gráfico %1</translation>
    </message>
    <message>
        <location line="+44" />
        <source>Mechanical energy [J]</source>
        <translation>Energía mecánica [J]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Largest contact force [kN]</source>
        <translation>Mayor fuerza de contacto [kN]</translation>
    </message>
    <message>
        <location line="+12" />
        <source>coordinate q [%1]</source>
        <translation>coordenada q [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>translation along %1 q_%2 [%3]</source>
        <translation>traslación según %1 q_%2 [%3]</translation>
    </message>
    <message>
        <location line="+4" />
        <source>rate dq/dt [%1]</source>
        <translation>velocidad dq/dt [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>velocity along %1 dq_%2/dt [%3]</source>
        <translation>velocidad según %1 dq_%2/dt [%3]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>drive force [%1]</source>
        <translation>fuerza del accionamiento [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>chamber A pressure p_A [%1]</source>
        <translation>presión de la cámara A p_A [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>chamber B pressure p_B [%1]</source>
        <translation>presión de la cámara B p_B [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>supply pressure p_S [%1]</source>
        <translation>presión de suministro p_S [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>delivered flow Q [%1]</source>
        <translation>caudal entregado Q [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction moment about A [%1]</source>
        <translation>momento de reacción en A [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction moment about R [%1]</source>
        <translation>momento de reacción en R [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction moment about T [%1]</source>
        <translation>momento de reacción en T [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction force along A [%1]</source>
        <translation>fuerza de reacción según A [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction force along R [%1]</source>
        <translation>fuerza de reacción según R [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction force along T [%1]</source>
        <translation>fuerza de reacción según T [%1]</translation>
    </message>
    <message>
        <location line="+31" />
        <location line="+128" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+31" />
        <source>Cannot save the image %1</source>
        <translation>No se puede guardar la imagen %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Export plots as CSV</source>
        <translation>Exportar gráficos como CSV</translation>
    </message>
    <message>
        <location line="+0" />
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Save plots as PNG</source>
        <translation>Guardar gráficos como PNG</translation>
    </message>
    <message>
        <location line="+0" />
        <source>PNG images (*.png)</source>
        <translation>Imágenes PNG (*.png)</translation>
    </message>
</context>
<context>
    <name>studio::ProblemsView</name>
    <message>
        <location filename="../ide/studio/editor/problems_view.cpp" line="+45" />
        <source>Line:col</source>
        <translation>Línea:col</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Hint</source>
        <translation>Sugerencia</translation>
    </message>
    <message>
        <location line="+37" />
        <source>%1 at %2: %3</source>
        <translation>%1 en %2: %3</translation>
    </message>
</context>
<context>
    <name>studio::ProfileDocument</name>
    <message>
        <location filename="../ide/studio/station/profile_document.cpp" line="+75" />
        <source>Cannot open the profile “%1”: %2</source>
        <translation>No se puede abrir el perfil “%1”: %2</translation>
    </message>
    <message>
        <location line="+62" />
        <source>Cannot import %1: %2</source>
        <translation>No se puede importar %1: %2</translation>
    </message>
</context>
<context>
    <name>studio::RecordsView</name>
    <message>
        <location filename="../ide/studio/train/records_view.cpp" line="+58" />
        <source>running</source>
        <translation>en curso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>finished</source>
        <translation>terminado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>stopped</source>
        <translation>detenido</translation>
    </message>
    <message>
        <location line="+1" />
        <source>interrupted</source>
        <translation>interrumpido</translation>
    </message>
    <message>
        <location line="+124" />
        <source>Trainee records</source>
        <translation>Registros de aprendices</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Operators</source>
        <translation>Operadores</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Code</source>
        <translation>Código</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Attempts</source>
        <translation>Intentos</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Passed</source>
        <translation>Aprobados</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Last attempt</source>
        <translation>Último intento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>code</source>
        <translation>código</translation>
    </message>
    <message>
        <location line="+1" />
        <source>name</source>
        <translation>nombre</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+46" />
        <source>Add operator</source>
        <translation>Agregar operador</translation>
    </message>
    <message>
        <location line="-45" />
        <source>Attempts (newest first)</source>
        <translation>Intentos (el más reciente primero)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Started</source>
        <translation>Inicio</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Tutorial</source>
        <translation>Tutorial</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Score</source>
        <translation>Puntaje</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Time [s]</source>
        <translation>Tiempo [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Breakdown</source>
        <translation>Desglose</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Measure</source>
        <translation>Medida</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Points</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Of</source>
        <translation>De</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Events</source>
        <translation>Eventos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back to the course</source>
        <translation>Volver al curso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Refresh</source>
        <translation>Actualizar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Export CSV…</source>
        <translation>Exportar CSV…</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Trainees see the expert in Trainer Mode</source>
        <translation>Los aprendices ven al experto en el modo quiosco</translation>
    </message>
    <message>
        <location line="+1" />
        <source>In Trainer Mode the trainee cannot change this: the expert's translucent machine runs beside each attempt only when it is on.</source>
        <translation>En el modo quiosco el aprendiz no puede cambiarlo: la máquina translúcida del experto acompaña cada intento solo si está activado.</translation>
    </message>
    <message>
        <location line="+31" />
        <location line="+4" />
        <source>Export CSV</source>
        <translation>Exportar CSV</translation>
    </message>
    <message>
        <location line="-3" />
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>Archivos CSV (*.csv);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+79" />
        <location line="+168" />
        <location line="+17" />
        <source>There are no trainee records.</source>
        <translation>No hay registros de aprendices.</translation>
    </message>
    <message>
        <location line="-182" />
        <source>The trainee records cannot be read: %1 Training goes on; attempts are kept in pending files and added to the records the next time they open.</source>
        <translation>No se pueden leer los registros de aprendices: %1 El entrenamiento continúa; los intentos se guardan en archivos pendientes y se agregan a los registros la próxima vez que se abran.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The trainee records are open read-only: %1</source>
        <translation>Los registros de aprendices están abiertos solo para lectura: %1</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Guest</source>
        <translation>Invitado</translation>
    </message>
    <message>
        <location line="+31" />
        <source>passed</source>
        <translation>aprobado</translation>
    </message>
    <message>
        <location line="+0" />
        <source>not passed</source>
        <translation>no aprobado</translation>
    </message>
    <message>
        <location line="+35" />
        <source>%1 s — %2</source>
        <translation>%1 s — %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(−%1)</source>
        <translation>(−%1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>No events.</source>
        <translation>Sin eventos.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Score of each attempt</source>
        <translation>Puntaje de cada intento</translation>
    </message>
    <message>
        <location line="+3" />
        <source>attempt</source>
        <translation>intento</translation>
    </message>
    <message>
        <location line="+3" />
        <source>score</source>
        <translation>puntaje</translation>
    </message>
    <message>
        <location line="+37" />
        <source>pass mark %1 (%2)</source>
        <translation>puntaje de aprobación %1 (%2)</translation>
    </message>
    <message>
        <location line="+28" />
        <source>Type the operator's code (badge number…).</source>
        <translation>Escriba el código del operador (número de credencial…).</translation>
    </message>
    <message numerus="yes">
        <location line="+18" />
        <source>Wrote %n attempt(s) to %1.</source>
        <translation><numerusform>Se escribió %n intento en %1.</numerusform><numerusform>Se escribieron %n intentos en %1.</numerusform></translation>
    </message>
</context>
<context>
    <name>studio::ResultScreen</name>
    <message>
        <location filename="../ide/studio/train/result_screen.cpp" line="+82" />
        <source>Measure</source>
        <translation>Medida</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Measured</source>
        <translation>Medido</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Points</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Of</source>
        <translation>De</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Score</source>
        <translation>Puntaje</translation>
    </message>
    <message>
        <location line="+1" />
        <source>What to improve</source>
        <translation>Qué mejorar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Course</source>
        <translation>Curso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Retry</source>
        <translation>Reintentar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Debrief</source>
        <translation>Análisis del intento</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next stage</source>
        <translation>Etapa siguiente</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save as demonstration…</source>
        <translation>Guardar como demostración…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Saves the operator's input of this attempt as an input log.</source>
        <translation>Guarda las entradas del operador en este intento como un registro de entradas.</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+27" />
        <source>Use as this stage's demonstration</source>
        <translation>Usar como demostración de esta etapa</translation>
    </message>
    <message>
        <location line="-26" />
        <source>From now on the demonstration, the expert and the comparison of this stage replay this attempt's input instead of the shipped one.</source>
        <translation>Desde ahora la demostración, el experto y la comparación de esta etapa reproducen las entradas de este intento en lugar de las incluidas.</translation>
    </message>
    <message>
        <location line="+12" />
        <location line="+6" />
        <source>Save as demonstration</source>
        <translation>Guardar como demostración</translation>
    </message>
    <message>
        <location line="-3" />
        <source>Padrob input logs (*.log);;All files (*)</source>
        <translation>Registros de entradas de Padrob (*.log);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+38" />
        <source>PASSED</source>
        <translation>APROBADO</translation>
    </message>
    <message>
        <location line="+0" />
        <source>NOT PASSED</source>
        <translation>NO APROBADO</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The time ran out.</source>
        <translation>Se acabó el tiempo.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The machine hit the scene too hard.</source>
        <translation>La máquina golpeó la escena con demasiada fuerza.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The machine touched a worker.</source>
        <translation>La máquina tocó a un trabajador.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The attempt was stopped.</source>
        <translation>El intento se detuvo.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The input ended before the goals were done.</source>
        <translation>Las entradas terminaron antes de cumplir los objetivos.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The simulation failed.</source>
        <translation>La simulación falló.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Score %1 of 100 in %2 s</source>
        <translation>Puntaje %1 de 100 en %2 s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Work done: %1 % of the stage</source>
        <translation>Trabajo hecho: %1 % de la etapa</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The trainee records could not be written (%1); the attempt is kept and will be added the next time they can.</source>
        <translation>No se pudieron escribir los registros de aprendices (%1); el intento se guarda y se agregará la próxima vez que se pueda.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>This attempt is now the stage's demonstration.</source>
        <translation>Este intento es ahora la demostración de la etapa.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 m/s³</source>
        <translation>%1 m/s³</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 penalty points</source>
        <translation>%1 puntos de penalización</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Nothing: a clean run.</source>
        <translation>Nada: un intento limpio.</translation>
    </message>
</context>
<context>
    <name>studio::SceneFile</name>
    <message>
        <location filename="../ide/studio/view/scene_file.cpp" line="+28" />
        <source>no such file</source>
        <translation>el archivo no existe</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cannot read the scene %1: %2</source>
        <translation>No se puede leer la escena %1: %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The scene %1 is too large (over %2 MB).</source>
        <translation>La escena %1 es demasiado grande (más de %2 MB).</translation>
    </message>
    <message>
        <location line="+17" />
        <source>The scene %1 has errors:
%2</source>
        <translation>La escena %1 tiene errores:
%2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The scene %1 has no ground graphics (G … B 0) to draw.</source>
        <translation>La escena %1 no tiene gráficos fijos a tierra (G … B 0) que dibujar.</translation>
    </message>
    <message numerus="yes">
        <location line="+7" />
        <source>%n graphic(s) on moving bodies of the scene are not drawn.</source>
        <translation>
            <numerusform>%n gráfico de un cuerpo móvil de la escena no se dibuja.</numerusform>
            <numerusform>%n gráficos de cuerpos móviles de la escena no se dibujan.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>studio::SerialConsoleDialog</name>
    <message>
        <location filename="../ide/studio/station/serial_console_dialog.cpp" line="+54" />
        <source>Add serial console</source>
        <translation>Agregar consola serie</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A replica console (levers on a DAQ box) on a serial port. The station opens it while this profile is in use, and tries again when it is unplugged.</source>
        <translation>Una consola réplica (palancas en una caja de adquisición de datos) en un puerto serie. El puesto la abre mientras este perfil está en uso, y vuelve a intentarlo cuando se desconecta.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>serial number %1</source>
        <translation>número de serie %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>e.g. /dev/ttyACM0</source>
        <translation>p. ej. /dev/ttyACM0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The port's name exactly as the profile will keep it (a /dev/serial/by-id/… link stays the same when the box is plugged elsewhere)</source>
        <translation>El nombre del puerto tal como lo guardará el perfil (un enlace /dev/serial/by-id/… no cambia cuando la caja se conecta en otro puerto)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Port:</source>
        <translation>Puerto:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Baud rate:</source>
        <translation>Velocidad (baudios):</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Add</source>
        <translation>Agregar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location line="+13" />
        <source>No serial port found now; type the port's name.</source>
        <translation>No se encontró ningún puerto serie; escriba el nombre del puerto.</translation>
    </message>
</context>
<context>
    <name>studio::SimulationRunner</name>
    <message>
        <location filename="../ide/studio/sim/simulation_runner.cpp" line="+459" />
        <source>The simulation stopped: %1</source>
        <translation>La simulación se detuvo: %1</translation>
    </message>
    <message>
        <location line="+65" />
        <source>The simulation cannot start: %1</source>
        <translation>La simulación no puede comenzar: %1</translation>
    </message>
</context>
<context>
    <name>studio::StartScreen</name>
    <message>
        <location filename="../ide/studio/train/start_screen.cpp" line="+56" />
        <source>Watch the demonstration</source>
        <translation>Ver la demostración</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back to the course</source>
        <translation>Volver al curso</translation>
    </message>
    <message>
        <location line="+26" />
        <location line="+47" />
        <location line="+73" />
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location line="-120" />
        <location line="+47" />
        <location line="+106" />
        <location line="+20" />
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <location line="-142" />
        <source>Speed:</source>
        <translation>Velocidad:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Expert's camera</source>
        <translation>Cámara del experto</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Look where the expert looked while recording (untick to move the view yourself).</source>
        <translation>Mirar hacia donde miraba el experto al grabar (desmarque para mover la vista usted mismo).</translation>
    </message>
    <message>
        <location line="+59" />
        <source>Time limit: %1 s. Pass mark: %2 of 100.</source>
        <translation>Tiempo límite: %1 s. Puntaje de aprobación: %2 de 100.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>How to drive (%1):</source>
        <translation>Cómo manejar la máquina (%1):</translation>
    </message>
    <message>
        <location line="+5" />
        <source>This tutorial has no demonstration.</source>
        <translation>Este tutorial no tiene demostración.</translation>
    </message>
    <message>
        <location line="+43" />
        <source>%1 s of %2 s</source>
        <translation>%1 s de %2 s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Done: passed, %1 of 100</source>
        <translation>Terminado: aprobado, %1 de 100</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Done</source>
        <translation>Terminado</translation>
    </message>
</context>
<context>
    <name>studio::StationHud</name>
    <message>
        <location filename="../ide/studio/station/live_state.cpp" line="+26" />
        <source>Bank: &lt;b&gt;%1&lt;/b&gt; (%2 of %3)</source>
        <translation>Banco: &lt;b&gt;%1&lt;/b&gt; (%2 de %3)</translation>
    </message>
</context>
<context>
    <name>studio::StationPage</name>
    <message>
        <location line="+44" />
        <source>Connected</source>
        <translation>Conectado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Disconnected</source>
        <translation>Desconectado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stalled</source>
        <translation>Sin respuesta</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Failed</source>
        <translation>Falló</translation>
    </message>
    <message>
        <location filename="../ide/studio/station/station_page.cpp" line="+62" />
        <source>The bank of mappings the operator's levers drive now</source>
        <translation>El banco de asignaciones que accionan ahora las palancas del operador</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Valve mapping</source>
        <translation>Asignación de válvulas</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Remove bank</source>
        <translation>Quitar banco</translation>
    </message>
    <message>
        <location line="+51" />
        <source>Profile:</source>
        <translation>Perfil:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The station profiles of this model: yours, and those shipped with it</source>
        <translation>Los perfiles de puesto de este modelo: los suyos y los que vienen con él</translation>
    </message>
    <message>
        <location line="+1" />
        <source>New</source>
        <translation>Nuevo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>An empty profile with one bank</source>
        <translation>Un perfil vacío con un banco</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save the profile under its name (a shipped profile is saved as your own copy)</source>
        <translation>Guardar el perfil con su nombre (un perfil incluido se guarda como copia suya)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save As…</source>
        <translation>Guardar como…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Delete this profile of yours (shipped profiles cannot be deleted)</source>
        <translation>Eliminar este perfil suyo (los perfiles incluidos no se pueden eliminar)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Import…</source>
        <translation>Importar…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Add a profile file (from another station) to this model's profiles</source>
        <translation>Agregar un archivo de perfil (de otro puesto) a los perfiles de este modelo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Export…</source>
        <translation>Exportar…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Write this profile to a file</source>
        <translation>Escribir este perfil en un archivo</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Problems of this profile with this model: a mapping with a warning is ignored</source>
        <translation>Problemas de este perfil con este modelo: una asignación con advertencia se ignora</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Devices</source>
        <translation>Dispositivos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Device</source>
        <translation>Dispositivo</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Samples</source>
        <translation>Muestras</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Dropped</source>
        <translation>Descartadas</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Readings dropped as corrupt (a serial line with a bad checksum…)</source>
        <translation>Lecturas descartadas por corruptas (una línea serie con suma de verificación errónea…)</translation>
    </message>
    <message>
        <location line="+33" />
        <source>Add serial console…</source>
        <translation>Agregar consola serie…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A replica console (DAQ box) on a serial port, kept in the profile</source>
        <translation>Una consola réplica (caja de adquisición de datos) en un puerto serie, guardada en el perfil</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove the selected device from the profile (only devices the profile opens: joysticks and gamepads are found by themselves)</source>
        <translation>Quitar del perfil el dispositivo seleccionado (solo los dispositivos que abre el perfil: los joysticks y gamepads se detectan solos)</translation>
    </message>
    <message>
        <location line="-6" />
        <location line="+464" />
        <source>Record input…</source>
        <translation>Grabar entradas…</translation>
    </message>
    <message>
        <location line="-456" />
        <source>Write everything the devices read to an input log</source>
        <translation>Escribir todo lo que leen los dispositivos en un registro de entradas</translation>
    </message>
    <message>
        <location line="-7" />
        <location line="+465" />
        <source>Replay a log…</source>
        <translation>Reproducir registro…</translation>
    </message>
    <message>
        <location line="-457" />
        <source>Play a recorded input log: it drives the machine instead of the operator</source>
        <translation>Reproducir un registro de entradas grabado: mueve la máquina en lugar del operador</translation>
    </message>
    <message>
        <location line="+26" />
        <source>Channels</source>
        <translation>Canales</translation>
    </message>
    <message>
        <location line="+51" />
        <source>(no name)</source>
        <translation>(sin nombre)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 (not saved)</source>
        <translation>%1 (sin guardar)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>This profile is not saved yet</source>
        <translation>Este perfil aún no se ha guardado</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 (unreadable)</source>
        <translation>%1 (ilegible)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 (shipped)</source>
        <translation>%1 (incluido)</translation>
    </message>
    <message>
        <location line="+63" />
        <source>Unsaved changes</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The profile “%1” has changes that are not saved. Discard them?</source>
        <translation>El perfil “%1” tiene cambios sin guardar. ¿Descartarlos?</translation>
    </message>
    <message>
        <location line="+43" />
        <source>New profile</source>
        <translation>Perfil nuevo</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Name of the new profile:</source>
        <translation>Nombre del perfil nuevo:</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Bank 1</source>
        <translation>Banco 1</translation>
    </message>
    <message>
        <location line="+14" />
        <source>Save profile as</source>
        <translation>Guardar perfil como</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Name of the profile:</source>
        <translation>Nombre del perfil:</translation>
    </message>
    <message>
        <location line="+9" />
        <source>A profile needs a name.</source>
        <translation>Un perfil necesita un nombre.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Replace profile</source>
        <translation>Reemplazar perfil</translation>
    </message>
    <message>
        <location line="+0" />
        <source>A profile named “%1” exists already for this model. Replace it?</source>
        <translation>Ya existe un perfil llamado “%1” para este modelo. ¿Reemplazarlo?</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Cannot save the profile: %1</source>
        <translation>No se puede guardar el perfil: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save profile</source>
        <translation>Guardar perfil</translation>
    </message>
    <message>
        <location line="+18" />
        <location line="+4" />
        <source>Delete profile</source>
        <translation>Eliminar perfil</translation>
    </message>
    <message>
        <location line="-4" />
        <source>Delete the profile “%1”? This cannot be undone.</source>
        <translation>¿Eliminar el perfil “%1”? Esto no se puede deshacer.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Cannot delete the profile: %1</source>
        <translation>No se puede eliminar el perfil: %1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Import station profile</source>
        <translation>Importar perfil de puesto</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Station profiles (*.json);;All files (*)</source>
        <translation>Perfiles de puesto (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Import profile</source>
        <translation>Importar perfil</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Export station profile</source>
        <translation>Exportar perfil de puesto</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Station profiles (*.json)</source>
        <translation>Perfiles de puesto (*.json)</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+6" />
        <source>Export profile</source>
        <translation>Exportar perfil</translation>
    </message>
    <message>
        <location line="-6" />
        <location filename="../ide/studio/station/station_page_devices.cpp" line="+82" />
        <source>%1 exists already. Replace it?</source>
        <translation>%1 ya existe. ¿Reemplazarlo?</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Cannot export the profile: %1</source>
        <translation>No se puede exportar el perfil: %1</translation>
    </message>
    <message>
        <location filename="../ide/studio/station/station_page_devices.cpp" line="-55" />
        <source>Add serial console</source>
        <translation>Agregar consola serie</translation>
    </message>
    <message>
        <location line="+0" />
        <source>“%1” is not a serial port (serial:/dev/…)</source>
        <translation>“%1” no es un puerto serie (serial:/dev/…)</translation>
    </message>
    <message>
        <location line="+51" />
        <location line="+4" />
        <location line="+4" />
        <location line="+17" />
        <source>Record input</source>
        <translation>Grabar entradas</translation>
    </message>
    <message>
        <location line="-25" />
        <location line="+33" />
        <source>Padrob input logs (*.log);;All files (*)</source>
        <translation>Registros de entradas de Padrob (*.log);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="-25" />
        <source>Cannot record to %1: %2</source>
        <translation>No se puede grabar en %1: %2</translation>
    </message>
    <message>
        <location line="+17" />
        <source>The log %1 may be incomplete: %2</source>
        <translation>El registro %1 puede estar incompleto: %2</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+5" />
        <location line="+4" />
        <source>Replay a log</source>
        <translation>Reproducir registro</translation>
    </message>
    <message>
        <location line="-4" />
        <source>Cannot replay %1: %2</source>
        <translation>No se puede reproducir %1: %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 has no devices to replay</source>
        <translation>%1 no tiene dispositivos que reproducir</translation>
    </message>
    <message>
        <location filename="../ide/studio/station/station_page.cpp" line="+30" />
        <source>● Recording to %1 (%2 s)</source>
        <translation>● Grabando en %1 (%2 s)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>▶ Replaying %1</source>
        <translation>▶ Reproduciendo %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Error — %1</source>
        <translation>Error — %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Warning — %1</source>
        <translation>Advertencia — %1</translation>
    </message>
    <message>
        <location line="+17" />
        <source>No banks</source>
        <translation>Sin bancos</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Bank %1</source>
        <translation>Banco %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Bank: %1 (%2 of %3)</source>
        <translation>Banco: %1 (%2 de %3)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Bank: %1</source>
        <translation>Banco: %1</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Replaying %1: the operator's devices are ignored</source>
        <translation>Reproduciendo %1: se ignoran los dispositivos del operador</translation>
    </message>
    <message>
        <location line="+29" />
        <source>%1 (replay)</source>
        <translation>%1 (reproducción)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1
Kind: %2
Id: %3</source>
        <translation>%1
Tipo: %2
Id: %3</translation>
    </message>
    <message>
        <location line="+19" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Stop recording</source>
        <translation>Detener grabación</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Stop replay</source>
        <translation>Detener reproducción</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Yes</source>
        <translation>Sí</translation>
    </message>
    <message>
        <location line="+1" />
        <source>No</source>
        <translation>No</translation>
    </message>
    <message>
        <location line="+10" />
        <location line="+26" />
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <location line="-25" />
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>studio::TrainPage</name>
    <message>
        <location filename="../ide/studio/train/train_page.cpp" line="+149" />
        <source>Trainee records</source>
        <translation>Registros de aprendices</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The trainer's PIN:</source>
        <translation>El PIN del instructor:</translation>
    </message>
    <message>
        <location line="+218" />
        <source>On the centre's network as %1</source>
        <translation>En la red del centro como %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>On the centre's network as %1, but without the centre's key: the instructor's commands are refused (%2)</source>
        <translation>En la red del centro como %1, pero sin la clave del centro: se rechazan las órdenes del instructor (%2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Not on the centre's network: %1</source>
        <translation>Fuera de la red del centro: %1</translation>
    </message>
</context>
<context>
    <name>studio::TrainStation</name>
    <message>
        <location filename="../ide/studio/centre/train_station.cpp" line="+93" />
        <source>no key file was given (--centre-key)</source>
        <translation>no se indicó un archivo de clave (--centre-key)</translation>
    </message>
    <message>
        <location line="+16" />
        <source>DDS refused to join the domain</source>
        <translation>DDS no permitió entrar al dominio</translation>
    </message>
</context>
<context>
    <name>studio::TrainingController</name>
    <message>
        <location filename="../ide/studio/train/training_controller.cpp" line="+211" />
        <location line="+242" />
        <source>Guest</source>
        <translation>Invitado</translation>
    </message>
    <message>
        <location line="-157" />
        <source>The demonstration chosen for this stage (%1) cannot be read: %2. The shipped demonstration is used.</source>
        <translation>No se puede leer la demostración elegida para esta etapa (%1): %2. Se usa la demostración incluida.</translation>
    </message>
    <message>
        <location line="+52" />
        <source>There is no recorded input: only an attempt with the operator's controls is recorded.</source>
        <translation>No hay entradas grabadas: solo se graba un intento con los mandos del operador.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Cannot write %1.</source>
        <translation>No se puede escribir %1.</translation>
    </message>
</context>
<context>
    <name>studio::VideoRecorder</name>
    <message>
        <location filename="../ide/studio/view/video_recorder.cpp" line="+54" />
        <source>A video is being recorded already.</source>
        <translation>Ya se está grabando un video.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Recording a video needs the program ffmpeg, which was not found. Install it (on Debian and Ubuntu: sudo apt install ffmpeg) and try again.</source>
        <translation>Para grabar un video se necesita el programa ffmpeg, que no se encontró. Instálelo (en Debian y Ubuntu: sudo apt install ffmpeg) y vuelva a intentarlo.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1 is not a regular file (a folder, a device or a pipe): it is not overwritten.</source>
        <translation>%1 no es un archivo común (es una carpeta, un dispositivo o una tubería): no se sobrescribe.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 is a file Padrob Studio has open (the model or the scene): it is not overwritten.</source>
        <translation>%1 es un archivo que Padrob Studio tiene abierto (el modelo o la escena): no se sobrescribe.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The folder %1 cannot be written.</source>
        <translation>No se puede escribir en la carpeta %1.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The 3D view cannot be drawn (no OpenGL 3.3): there is nothing to record.</source>
        <translation>La vista 3D no se puede dibujar (no hay OpenGL 3.3): no hay nada que grabar.</translation>
    </message>
    <message>
        <location line="+24" />
        <source>ffmpeg (%1) could not be started: %2</source>
        <translation>No se pudo iniciar ffmpeg (%1): %2</translation>
    </message>
    <message>
        <location line="+58" />
        <source>ffmpeg stopped with an error while writing %1</source>
        <translation>ffmpeg se detuvo con un error al escribir %1</translation>
    </message>
</context>
<context>
    <name>studio::Viewport</name>
    <message>
        <location filename="../ide/studio/view/scene_geometry.cpp" line="+164" />
        <source>no file named</source>
        <translation>no se indicó un archivo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the file was not found (looked for %1)</source>
        <translation>no se encontró el archivo (se buscó %1)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the file holds no triangles</source>
        <translation>el archivo no contiene triángulos</translation>
    </message>
    <message>
        <location line="+1" />
        <source>it cannot be read: %1</source>
        <translation>no se puede leer: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Graphic %1 (body %2): mesh "%3" is drawn as a box: %4.</source>
        <translation>Gráfico %1 (cuerpo %2): la malla "%3" se dibuja como una caja: %4.</translation>
    </message>
    <message>
        <location filename="../ide/studio/view/viewport.cpp" line="+226" />
        <source>Iso</source>
        <translation>Iso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Front</source>
        <translation>Frente</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Side</source>
        <translation>Lateral</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Top</source>
        <translation>Superior</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Operator seat</source>
        <translation>Asiento del operador</translation>
    </message>
    <message>
        <location line="+107" />
        <source>The 3D view needs OpenGL 3.3, which this system does not provide.</source>
        <translation>La vista 3D necesita OpenGL 3.3, que este sistema no ofrece.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The 3D view's shaders do not build: %1</source>
        <translation>Los shaders de la vista 3D no se compilan: %1</translation>
    </message>
</context>
<context>
    <name>studio::ViewportLayout</name>
    <message>
        <location filename="../ide/studio/view/viewport_layout.cpp" line="+45" />
        <source>The operator's screens are shown in separate windows.</source>
        <translation>Las pantallas del operador se muestran en ventanas separadas.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Operator screen %1 of %2</source>
        <translation>Pantalla del operador %1 de %2</translation>
    </message>
</context>
<context>
    <name>studio::main</name>
    <message>
        <location filename="../ide/studio/main.cpp" line="+85" />
        <source>Padrob Studio: write a machine's model, simulate it in real time and drive it from the operator's devices.</source>
        <translation>Padrob Studio: escriba el modelo de una máquina, simúlelo en tiempo real y opérelo desde los dispositivos del operador.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>The model file to open (default: the liner manipulator).</source>
        <translation>El archivo de modelo que se abre (por defecto: la lainera).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Draw the ground graphics of FILE around the model (a scene such as resources/scenes/sag_mill.pad). Without it, the scene used last.</source>
        <translation>Dibujar los gráficos fijos a tierra de ARCHIVO alrededor del modelo (una escena como resources/scenes/sag_mill.pad). Sin esta opción, la última escena usada.</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+41" />
        <location line="+25" />
        <source>FILE</source>
        <translation>ARCHIVO</translation>
    </message>
    <message>
        <location line="-63" />
        <source>Measure instead of working, then quit: the start-up time, N frames of a 1920x1080 window paced at 60 Hz and N back to back, with one view and with three, the solver's step periods meanwhile, and the latency of 60 key presses to the solver.</source>
        <translation>Medir en vez de trabajar, y luego salir: el tiempo de inicio, N cuadros de una ventana de 1920x1080 a 60 Hz y N seguidos, con una vista y con tres, los periodos de paso del solver mientras tanto, y la latencia de 60 pulsaciones de tecla hasta el solver.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>With --bench-frames: only one view (1) or only three (3).</source>
        <translation>Con --bench-frames: solo una vista (1) o solo tres (3).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>With --bench-frames: print the results as one JSON object.</source>
        <translation>Con --bench-frames: escribir los resultados como un objeto JSON.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Kiosk mode for the training room: only the Train workspace, full screen, without menus. Ctrl+Shift+F12 leaves it (asking the trainer's PIN when one is set).</source>
        <translation>Modo quiosco para la sala de entrenamiento: solo el espacio Entrenamiento, a pantalla completa, sin menús. Ctrl+Shift+F12 sale de él (pidiendo el PIN del instructor si hay uno).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>With --trainer: the operator in training.</source>
        <translation>Con --trainer: el operador en entrenamiento.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The language of the application and the tutorials (es or en).</source>
        <translation>El idioma de la aplicación y de los tutoriales (es o en).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Where the 3D view computes its light: at every pixel (finer), at the vertices (faster on a software OpenGL), or auto: at the vertices on a software OpenGL, at every pixel on a GPU. Without it, the choice made in Settings &gt; Lighting (auto at first; --bench-frames: auto).</source>
        <translation>Dónde calcula la luz la vista 3D: en cada píxel (pixel, más fina), en los vértices (vertex, más rápida con un OpenGL por software) o auto: en los vértices con un OpenGL por software y en cada píxel con una GPU. Sin ella, lo elegido en Configuración &gt; Iluminación (auto al principio; con --bench-frames: auto).</translation>
    </message>
    <message>
        <location line="+55" />
        <source>Make the Train workspace a station of the training centre named NAME (unique in the centre): it publishes its attempt and obeys the instructor's signed commands.</source>
        <translation>Convierte el espacio Entrenar en un puesto del centro de entrenamiento llamado NOMBRE (único en el centro): publica su intento y obedece las órdenes firmadas del instructor.</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+12" />
        <source>NAME</source>
        <translation>NOMBRE</translation>
    </message>
    <message>
        <location line="-9" />
        <source>DDS Security: authenticated, access-controlled, encrypted traffic, with the centre's PKI in DIR and this node's identity in DIR/nodes/NAME (see 'padrob centre pki').</source>
        <translation>DDS Security: tráfico autenticado, con control de acceso y cifrado, con la PKI del centro en CARPETA y la identidad de este nodo en CARPETA/nodes/NOMBRE (vea 'padrob centre pki').</translation>
    </message>
    <message>
        <location line="+3" />
        <source>DIR</source>
        <translation>CARPETA</translation>
    </message>
    <message>
        <location line="+3" />
        <source>With --instructor or --display-of: this node's name in the centre (its identity in the PKI with --security). Default: instructor@HOST, display-STATION-VIEW.</source>
        <translation>Con --instructor o --display-of: el nombre de este nodo en el centro (su identidad en la PKI con --security). Por omisión: instructor@HOST, display-PUESTO-VISTA.</translation>
    </message>
    <message>
        <location line="+18" />
        <source>--lang must be es or en.</source>
        <translation>--lang debe ser es o en.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>--lighting must be auto, pixel or vertex.</source>
        <translation>--lighting debe ser auto, pixel o vertex.</translation>
    </message>
    <message>
        <location line="+18" />
        <source>--bench-frames needs a number of frames (1 or more) and --views 1 or 3.</source>
        <translation>--bench-frames necesita un número de cuadros (1 o más) y --views 1 o 3.</translation>
    </message>
    <message>
        <location line="-98" />
        <source>Be a display node of the training centre: show STATION's machine from its operator's seat, driven by its state stream.</source>
        <translation>Ser una pantalla del centro de entrenamiento: mostrar la máquina de PUESTO desde el asiento de su operador, movida por su flujo de estado.</translation>
    </message>
    <message>
        <location line="-60" />
        <source>Show this help and quit.</source>
        <translation>Mostrar esta ayuda y salir.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Show the version and quit.</source>
        <translation>Mostrar la versión y salir.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>model</source>
        <translation>modelo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>[MODEL]</source>
        <translation>[MODELO]</translation>
    </message>
    <message>
        <location line="+45" />
        <source>Start as usual, save the window to FILE (PNG) once the model is drawn, print the model's file, and quit.</source>
        <translation>Iniciar como de costumbre, guardar la ventana en ARCHIVO (PNG) cuando el modelo esté dibujado, mostrar el archivo del modelo y salir.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>STATION</source>
        <translation>PUESTO</translation>
    </message>
    <message>
        <location line="+3" />
        <source>With --display-of: which of the station's three screens (default centre).</source>
        <translation>Con --display-of: cuál de las tres pantallas del puesto (por defecto la central).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Be the instructor's station of the training centre: watch the stations and command them.</source>
        <translation>Ser el puesto del instructor del centro de entrenamiento: observar los puestos y darles órdenes.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>With --instructor, --display-of or --station-name: the centre's key, which signs everything a node of the centre says and checks everything it hears (without it the instructor and the display see nothing, and the station refuses every command and is heard by no one).</source>
        <translation>Con --instructor, --display-of o --station-name: la clave del centro, que firma todo lo que dice un nodo del centro y verifica todo lo que escucha (sin ella el instructor y la pantalla no ven nada, y el puesto rechaza toda orden y nadie lo escucha).</translation>
    </message>
    <message>
        <location line="+8" />
        <source>The training centre's DDS domain, 0-232 (default 0).</source>
        <translation>El dominio DDS del centro de entrenamiento, 0-232 (por defecto 0).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The training centre on this computer only.</source>
        <translation>El centro de entrenamiento solo en este computador.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The network interface of the training centre (name or address; repeatable).</source>
        <translation>La interfaz de red del centro de entrenamiento (nombre o dirección; repetible).</translation>
    </message>
    <message>
        <location line="+2" />
        <source>INTERFACE</source>
        <translation>INTERFAZ</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Find the centre's other computers by unicast at ADDRESS (repeatable; without it, multicast).</source>
        <translation>Encontrar los otros computadores del centro por unicast en DIRECCIÓN (repetible; sin esta opción, multicast).</translation>
    </message>
    <message>
        <location line="+2" />
        <source>ADDRESS</source>
        <translation>DIRECCIÓN</translation>
    </message>
    <message>
        <location line="+89" />
        <source>--domain must be a whole number from 0 to 232.</source>
        <translation>--domain debe ser un número entero de 0 a 232.</translation>
    </message>
    <message>
        <location line="+15" />
        <source>--station-name needs a name.</source>
        <translation>--station-name necesita un nombre.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>--view must be left, centre or right.</source>
        <translation>--view debe ser left, centre o right.</translation>
    </message>
</context>
<context>
    <name>trainer::ChannelCalibration</name>
    <message>
        <location filename="../trainer/station/calibration.cpp" line="+36" />
        <source>a value is not a number</source>
        <translation>un valor no es un número</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the raw minimum must be below the raw maximum</source>
        <translation>el mínimo crudo debe ser menor que el máximo crudo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the centre must lie between the minimum and the maximum</source>
        <translation>el centro debe estar entre el mínimo y el máximo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>dead bands must be between 0 and 0.9 of the travel</source>
        <translation>las bandas muertas deben estar entre 0 y 0.9 del recorrido</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the exponential curve's parameter must be between 0.05 and 10</source>
        <translation>el parámetro de la curva exponencial debe estar entre 0.05 y 10</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the filter's cutoff cannot be negative</source>
        <translation>la frecuencia de corte del filtro no puede ser negativa</translation>
    </message>
    <message>
        <location line="+52" />
        <source>“%1” must be a number</source>
        <translation>“%1” debe ser un número</translation>
    </message>
    <message>
        <location line="+10" />
        <source>“%1” must be true or false</source>
        <translation>“%1” debe ser true o false</translation>
    </message>
    <message>
        <location line="+16" />
        <source>“curve” must be "linear" or "exponential"</source>
        <translation>“curve” debe ser "linear" o "exponential"</translation>
    </message>
    <message>
        <location line="+63" />
        <source>Leave the lever at rest to capture its centre.</source>
        <translation>Deje la palanca en reposo para capturar su centro.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Move the lever to its full travel, both ways.</source>
        <translation>Mueva la palanca por todo su recorrido, en ambos sentidos.</translation>
    </message>
</context>
<context>
    <name>trainer::ComediDaq</name>
    <message>
        <location filename="../trainer/input/comedi_daq.cpp" line="+11" />
        <source>Comedi card %1</source>
        <translation>Tarjeta Comedi %1</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Cannot open the Comedi card %1: %2. The card's kernel driver must be loaded and the device configured with comedi_config. Trying again every 2 s.</source>
        <translation>No se puede abrir la tarjeta Comedi %1: %2. El driver del kernel de la tarjeta debe estar cargado y el dispositivo configurado con comedi_config. Se reintenta cada 2 s.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>The Comedi card %1 has no analog inputs. Trying again every 2 s.</source>
        <translation>La tarjeta Comedi %1 no tiene entradas analógicas. Se reintenta cada 2 s.</translation>
    </message>
    <message>
        <location line="+14" />
        <source>AI %1</source>
        <translation>AI %1</translation>
    </message>
    <message>
        <location line="+37" />
        <source>Reading the Comedi card %1 failed (%2); trying again every 2 s.</source>
        <translation>Falló la lectura de la tarjeta Comedi %1 (%2); se reintenta cada 2 s.</translation>
    </message>
</context>
<context>
    <name>trainer::Gamepad</name>
    <message>
        <location filename="../trainer/station/control_names.cpp" line="+21" />
        <source>Left stick X</source>
        <translation>Stick izquierdo X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left stick Y</source>
        <translation>Stick izquierdo Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right stick X</source>
        <translation>Stick derecho X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right stick Y</source>
        <translation>Stick derecho Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left trigger</source>
        <translation>Gatillo izquierdo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right trigger</source>
        <translation>Gatillo derecho</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Back</source>
        <translation>Atrás</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Guide</source>
        <translation>Guía</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start</source>
        <translation>Inicio</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left stick press</source>
        <translation>Pulsar stick izquierdo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right stick press</source>
        <translation>Pulsar stick derecho</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left shoulder</source>
        <translation>Hombro izquierdo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right shoulder</source>
        <translation>Hombro derecho</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D-pad up</source>
        <translation>Cruceta arriba</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D-pad down</source>
        <translation>Cruceta abajo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D-pad left</source>
        <translation>Cruceta izquierda</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D-pad right</source>
        <translation>Cruceta derecha</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Misc</source>
        <translation>Otro</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Paddle %1</source>
        <translation>Paleta %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Touchpad</source>
        <translation>Panel táctil</translation>
    </message>
    <message>
        <location line="+8" />
        <source>LS</source>
        <comment>left stick pressed, on a small lamp</comment>
        <translation>LS</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RS</source>
        <comment>right stick pressed, on a small lamp</comment>
        <translation>RS</translation>
    </message>
    <message>
        <location line="+1" />
        <source>LB</source>
        <comment>left shoulder button, on a small lamp</comment>
        <translation>LB</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RB</source>
        <comment>right shoulder button, on a small lamp</comment>
        <translation>RB</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Axis %1</source>
        <translation>Eje %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Button %1</source>
        <translation>Botón %1</translation>
    </message>
</context>
<context>
    <name>trainer::InputDevice</name>
    <message>
        <location filename="../trainer/input/input_device.cpp" line="+10" />
        <source>Joystick</source>
        <translation>Joystick</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gamepad</source>
        <translation>Gamepad</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Serial DAQ console</source>
        <translation>Consola DAQ serie</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Comedi DAQ card</source>
        <translation>Tarjeta DAQ Comedi</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Keyboard</source>
        <translation>Teclado</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Replay</source>
        <translation>Reproducción</translation>
    </message>
</context>
<context>
    <name>trainer::InputLog</name>
    <message>
        <location filename="../trainer/input/input_log.cpp" line="+13" />
        <source>line %1: %2</source>
        <translation>línea %1: %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>not a Padrob input log (the first line must be “%1”)</source>
        <translation>no es un registro de entradas de Padrob (la primera línea debe ser “%1”)</translation>
    </message>
    <message>
        <location line="+11" />
        <source>devices must be numbered 0, 1, 2… in order</source>
        <translation>los dispositivos deben numerarse 0, 1, 2… en orden</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the device description is not valid JSON (%1)</source>
        <translation>la descripción del dispositivo no es JSON válido (%1)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>a device needs an “id” and a known “kind”</source>
        <translation>un dispositivo necesita un “id” y un “kind” conocido</translation>
    </message>
    <message>
        <location line="+16" />
        <source>the time must be a number that never goes back</source>
        <translation>el tiempo debe ser un número que nunca retrocede</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the device number (the second field, after the time) is missing</source>
        <translation>falta el número de dispositivo (el segundo campo, después del tiempo)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>device %1 is not described above this line</source>
        <translation>el dispositivo %1 no está descrito antes de esta línea</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 values where device %2 has %3 axes and %4 buttons</source>
        <translation>%1 valores donde el dispositivo %2 tiene %3 ejes y %4 botones</translation>
    </message>
    <message>
        <location line="+7" />
        <source>axis %1 is not a number</source>
        <translation>el eje %1 no es un número</translation>
    </message>
    <message>
        <location line="+5" />
        <source>button %1 must be 0 or 1</source>
        <translation>el botón %1 debe ser 0 o 1</translation>
    </message>
    <message>
        <location line="+20" />
        <location line="+43" />
        <source>cannot write %1: %2</source>
        <translation>no se puede escribir %1: %2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Replay of %1</source>
        <translation>Reproducción de %1</translation>
    </message>
</context>
<context>
    <name>trainer::KeyboardDevice</name>
    <message>
        <location filename="../trainer/input/input_device.cpp" line="+8" />
        <location filename="../trainer/input/keyboard_device.cpp" line="+12" />
        <source>Keyboard</source>
        <translation>Teclado</translation>
    </message>
</context>
<context>
    <name>trainer::ProfileStore</name>
    <message>
        <location filename="../trainer/station/profile_store.cpp" line="+98" />
        <source>there is no profile “%1” for %2</source>
        <translation>no hay un perfil “%1” para %2</translation>
    </message>
    <message>
        <location line="+18" />
        <source>a profile needs a name</source>
        <translation>un perfil necesita un nombre</translation>
    </message>
    <message>
        <location line="+6" />
        <source>a profile named “%1” exists already</source>
        <translation>ya existe un perfil llamado “%1”</translation>
    </message>
    <message>
        <location line="+9" />
        <source>cannot keep the old %1 aside; nothing was saved</source>
        <translation>no se puede guardar aparte el %1 anterior; no se guardó nada</translation>
    </message>
    <message>
        <location line="+15" />
        <source>“%1” ships with the model and cannot be deleted</source>
        <translation>“%1” viene con el modelo y no se puede eliminar</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot delete %1</source>
        <translation>no se puede eliminar %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>there is no profile “%1”</source>
        <translation>no hay un perfil “%1”</translation>
    </message>
    <message>
        <location line="+26" />
        <source>%1 exists already</source>
        <translation>%1 ya existe</translation>
    </message>
</context>
<context>
    <name>trainer::SdlJoysticks</name>
    <message>
        <location filename="../trainer/input/sdl_joysticks.cpp" line="+110" />
        <source>SDL cannot open it: %1</source>
        <translation>SDL no lo puede abrir: %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>It has neither axes nor buttons, so it cannot drive a valve.</source>
        <translation>No tiene ejes ni botones, así que no puede mover una válvula.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>It has no axes, so it cannot drive a valve (its buttons can still be used).</source>
        <translation>No tiene ejes, así que no puede mover una válvula (sus botones sí se pueden usar).</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Unplugged; waiting for it to come back</source>
        <translation>Desconectado; esperando que vuelva</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Unnamed gamepad</source>
        <translation>Gamepad sin nombre</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Unnamed joystick</source>
        <translation>Joystick sin nombre</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Axis %1</source>
        <translation>Eje %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Button %1</source>
        <translation>Botón %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Hat %1 up</source>
        <translation>Cruceta %1 arriba</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hat %1 right</source>
        <translation>Cruceta %1 derecha</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hat %1 down</source>
        <translation>Cruceta %1 abajo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hat %1 left</source>
        <translation>Cruceta %1 izquierda</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Joysticks and gamepads cannot be used: SDL did not start (%1).</source>
        <translation>No se pueden usar joysticks ni gamepads: SDL no se inició (%1).</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Closed: the joystick back end was stopped</source>
        <translation>Cerrado: se detuvo el módulo de joysticks</translation>
    </message>
</context>
<context>
    <name>trainer::SerialDaq</name>
    <message>
        <location filename="../trainer/input/serial_daq.cpp" line="+40" />
        <location line="+223" />
        <source>DAQ console on %1</source>
        <translation>Consola DAQ en %1</translation>
    </message>
    <message>
        <location line="-208" />
        <source>device removed: %1</source>
        <translation>dispositivo retirado: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>read error or hang-up</source>
        <translation>error de lectura o corte de la conexión</translation>
    </message>
    <message>
        <location line="+2" />
        <source>write error</source>
        <translation>error de escritura</translation>
    </message>
    <message>
        <location line="+49" />
        <source>The console on %1 is disconnected (%2); trying again every second.</source>
        <translation>La consola en %1 está desconectada (%2); se reintenta cada segundo.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Cannot open %1: %2. Trying again every second.</source>
        <translation>No se puede abrir %1: %2. Se reintenta cada segundo.</translation>
    </message>
    <message>
        <location line="+27" />
        <source>The console on %1 was disconnected (%2); trying again every second.</source>
        <translation>La consola en %1 se desconectó (%2); se reintenta cada segundo.</translation>
    </message>
    <message>
        <location line="+82" />
        <source>No data from the console on %1 for %2 s.</source>
        <translation>Sin datos de la consola en %1 durante %2 s.</translation>
    </message>
    <message>
        <location line="+51" />
        <source>Lever %1</source>
        <translation>Palanca %1</translation>
    </message>
</context>
<context>
    <name>trainer::Station</name>
    <message>
        <location filename="../trainer/station/device_factory.cpp" line="+17" />
        <source>“serial:” needs a port name, e.g. serial:/dev/ttyACM0</source>
        <translation>“serial:” necesita el nombre de un puerto, p. ej. serial:/dev/ttyACM0</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1: this Padrob was built without Comedi (install libcomedi-dev and build again); the card is ignored</source>
        <translation>%1: este Padrob se compiló sin Comedi (instale libcomedi-dev y vuelva a compilar); se ignora la tarjeta</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1: unknown kind of device; it is ignored</source>
        <translation>%1: tipo de dispositivo desconocido; se ignora</translation>
    </message>
    <message>
        <location filename="../trainer/station/station.cpp" line="+116" />
        <source>the station is not running</source>
        <translation>el puesto no está funcionando</translation>
    </message>
</context>
<context>
    <name>trainer::StationEngine</name>
    <message>
        <location filename="../trainer/station/station_engine.cpp" line="+444" />
        <source>not connected</source>
        <translation>no conectado</translation>
    </message>
    <message>
        <location line="-12" />
        <source>valves closed, holding %1</source>
        <translation>válvulas cerradas, se mantienen %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the keyboard drives %1 instead</source>
        <translation>el teclado mueve %1 en su lugar</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: %2 — %3</source>
        <translation>%1: %2 — %3</translation>
    </message>
    <message>
        <location line="+14" />
        <source>%1, %2: device fault, it reads %3 where it can read only %4…%5 — valve closed%6</source>
        <translation>%1, %2: falla del dispositivo, lee %3 donde solo puede leer %4…%5 — válvula cerrada%6</translation>
    </message>
    <message>
        <location line="+3" />
        <source>, holding %1</source>
        <translation>, sosteniendo %1</translation>
    </message>
    <message>
        <location line="+16" />
        <source>No %1 found — %2</source>
        <translation>No se encontró %1 — %2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>the keyboard drives instead</source>
        <translation>el teclado las mueve en su lugar</translation>
    </message>
    <message>
        <location line="+1" />
        <source>its valves are closed, the machine holds</source>
        <translation>sus válvulas están cerradas, la máquina se mantiene</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>the keyboard drives %1 of its %n drive(s), the rest hold</source>
        <translation><numerusform>el teclado mueve %1 de su %n accionamiento, el resto se mantiene</numerusform><numerusform>el teclado mueve %1 de sus %n accionamientos, el resto se mantiene</numerusform></translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 missing — %2</source>
        <translation>Falta %1 — %2</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: next bank</source>
        <translation>%1: banco siguiente</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Calibrating: every valve is held closed</source>
        <translation>Calibrando: todas las válvulas se mantienen cerradas</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Bring the lever to centre to take over: %1</source>
        <translation>Lleve la palanca al centro para tomar el control: %1</translation>
    </message>
</context>
<context>
    <name>trainer::StationProfile</name>
    <message>
        <location filename="../trainer/station/profile.cpp" line="+48" />
        <location line="+8" />
        <source>“%1” is missing</source>
        <translation>falta “%1”</translation>
    </message>
    <message>
        <location line="-7" />
        <source>“%1” must be a text</source>
        <translation>“%1” debe ser un texto</translation>
    </message>
    <message>
        <location line="+10" />
        <source>“%1” must be a whole number</source>
        <translation>“%1” debe ser un número entero</translation>
    </message>
    <message>
        <location line="+8" />
        <source>“%1” must be a number</source>
        <translation>“%1” debe ser un número</translation>
    </message>
    <message>
        <location line="+8" />
        <source>“%1” must be a list</source>
        <translation>“%1” debe ser una lista</translation>
    </message>
    <message>
        <location line="+6" />
        <source>must be an object { … }</source>
        <translation>debe ser un objeto { … }</translation>
    </message>
    <message>
        <location line="+34" />
        <source>line %1, column %2</source>
        <translation>línea %1, columna %2</translation>
    </message>
    <message>
        <location line="+94" />
        <source>not a valid profile file (%1); fix the JSON or import the profile again</source>
        <translation>no es un archivo de perfil válido (%1); corrija el JSON o importe el perfil de nuevo</translation>
    </message>
    <message>
        <location line="+6" />
        <source>not a station profile: the file must hold one JSON object</source>
        <translation>no es un perfil del puesto: el archivo debe contener un objeto JSON</translation>
    </message>
    <message>
        <location line="+5" />
        <source>not a station profile (“format” must be "%1")</source>
        <translation>no es un perfil del puesto (“format” debe ser "%1")</translation>
    </message>
    <message>
        <location line="+8" />
        <source>made by a newer Padrob (profile version %1; this one reads up to %2). Update Padrob or use a profile saved by this version.</source>
        <translation>hecho por un Padrob más nuevo (versión de perfil %1; este lee hasta la %2). Actualice Padrob o use un perfil guardado por esta versión.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the version must be 1 or more</source>
        <translation>la versión debe ser 1 o mayor</translation>
    </message>
    <message>
        <location line="+65" />
        <source>“%1” must be translated by a text</source>
        <translation>“%1” debe traducirse por un texto</translation>
    </message>
    <message>
        <location line="+15" />
        <source>the mapping names no device</source>
        <translation>la asignación no indica ningún dispositivo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the axis must be 0 or more</source>
        <translation>el eje debe ser 0 o mayor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the sign must be 1 or -1</source>
        <translation>el signo debe ser 1 o -1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the gain must be between 0 and %1</source>
        <translation>la ganancia debe estar entre 0 y %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>drive C %1 is not in this model (or has no D statement); this mapping is ignored</source>
        <translation>el accionamiento C %1 no está en este modelo (o no tiene sentencia D); se ignora esta asignación</translation>
    </message>
    <message>
        <location line="+12" />
        <source>a bank button needs a device and a button number</source>
        <translation>un botón de banco necesita un dispositivo y un número de botón</translation>
    </message>
    <message>
        <location line="+9" />
        <source>“%1”: only serial DAQ ports (serial:…) and Comedi cards (comedi:…) are listed here</source>
        <translation>“%1”: aquí solo se indican puertos DAQ serie (serial:…) y tarjetas Comedi (comedi:…)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the baud rate must be positive</source>
        <translation>la velocidad en baudios debe ser positiva</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Keyboard and gamepad</source>
        <translation>Teclado y gamepad</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Made by Padrob for this model: key pairs Q/A, W/S, … on the drives in order, and a two-stick gamepad in banks of four drives, switched with the shoulder buttons.</source>
        <translation>Hecho por Padrob para este modelo: pares de teclas Q/A, W/S, … en los accionamientos en orden, y un gamepad de dos palancas en bancos de cuatro accionamientos, que se cambian con los botones superiores.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Bank %1</source>
        <translation>Banco %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Bank 1</source>
        <translation>Banco 1</translation>
    </message>
</context>
<context>
    <name>trainer::records::RecordsDb</name>
    <message>
        <location filename="../trainer/records/records_db.cpp" line="+288" />
        <source>the records database is in use by another program, which has kept it locked for over %1 s; close that program or try again</source>
        <translation>la base de datos de registros está en uso por otro programa, que la tiene bloqueada hace más de %1 s; cierre ese programa o intente de nuevo</translation>
    </message>
    <message>
        <location line="+12" />
        <source>the records database %1 is read-only (check the permissions of the file and of its folder)</source>
        <translation>la base de datos de registros %1 es de solo lectura (revise los permisos del archivo y de su carpeta)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the disk holding the records database %1 is full; free some space (nothing of this step was recorded)</source>
        <translation>el disco de la base de datos de registros %1 está lleno; libere espacio (no se registró nada de este paso)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the records database %1 is damaged (%2); keep a copy of the file and restore it from a backup</source>
        <translation>la base de datos de registros %1 está dañada (%2); guarde una copia del archivo y restáurela desde un respaldo</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the file is not a records database (not an SQLite database, or a damaged one)</source>
        <translation>el archivo no es una base de datos de registros (no es una base de datos SQLite, o está dañada)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>SQLite cannot open the file %1 (does its folder exist, and may Padrob write there?)</source>
        <translation>SQLite no puede abrir el archivo %1 (¿existe su carpeta, y puede Padrob escribir en ella?)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the disk reported an error on %1 (%2)</source>
        <translation>el disco informó un error en %1 (%2)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the PostgreSQL server's disk is full; ask its administrator to free some space (nothing of this step was recorded)</source>
        <translation>el disco del servidor PostgreSQL está lleno; pida a su administrador que libere espacio (no se registró nada de este paso)</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+31" />
        <source>the records database %1 is open read-only</source>
        <translation>la base de datos de registros %1 está abierta en solo lectura</translation>
    </message>
    <message>
        <location line="-29" />
        <source>the PostgreSQL user may not do this on %1 (%2); ask the server's administrator for the rights</source>
        <translation>el usuario de PostgreSQL no puede hacer esto en %1 (%2); pida los permisos al administrador del servidor</translation>
    </message>
    <message>
        <location line="+4" />
        <source>lost the connection to the PostgreSQL server %1 (%2)</source>
        <translation>se perdió la conexión con el servidor PostgreSQL %1 (%2)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the records database is not open</source>
        <translation>la base de datos de registros no está abierta</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the records database was opened in another thread (each thread needs a RecordsDb of its own)</source>
        <translation>la base de datos de registros se abrió en otro hilo (cada hilo necesita su propio RecordsDb)</translation>
    </message>
    <message>
        <location line="+73" />
        <location line="+58" />
        <location line="+60" />
        <source>cannot open the records database %1</source>
        <translation>no se puede abrir la base de datos de registros %1</translation>
    </message>
    <message>
        <location line="-115" />
        <source>the SQLite driver of Qt (QSQLITE) is not installed (on Debian: the package libqt6sql6-sqlite)</source>
        <translation>el driver SQLite de Qt (QSQLITE) no está instalado (en Debian: el paquete libqt6sql6-sqlite)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>it is a folder, not a file</source>
        <translation>es una carpeta, no un archivo</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the file is not a records database (not an SQLite database)</source>
        <translation>el archivo no es una base de datos de registros (no es una base de datos SQLite)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>there is no such file</source>
        <translation>no existe ese archivo</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot create its folder %1</source>
        <translation>no se puede crear su carpeta %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the file is read-only (check its permissions, or open the records read-only)</source>
        <translation>el archivo es de solo lectura (revise sus permisos, o abra los registros en solo lectura)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>its folder %1 is read-only, and SQLite writes its journal there (check the folder's permissions, or open the records read-only)</source>
        <translation>su carpeta %1 es de solo lectura, y SQLite escribe ahí su diario (revise los permisos de la carpeta, o abra los registros en solo lectura)</translation>
    </message>
    <message>
        <location line="+32" />
        <source>the PostgreSQL driver of Qt (QPSQL) is not installed (on Debian: the package libqt6sql6-psql); until it is, use the records file on this computer</source>
        <translation>el driver PostgreSQL de Qt (QPSQL) no está instalado (en Debian: el paquete libqt6sql6-psql); mientras tanto, use el archivo de registros de este computador</translation>
    </message>
    <message>
        <location line="+15" />
        <source>the PostgreSQL server did not accept the connection (%1)</source>
        <translation>el servidor PostgreSQL no aceptó la conexión (%1)</translation>
    </message>
    <message>
        <location line="+32" />
        <source>it holds other tables, not Padrob's records (left untouched)</source>
        <translation>contiene otras tablas, no los registros de Padrob (no se modificó)</translation>
    </message>
    <message>
        <location line="+16" />
        <source>it has schema version %1, newer than this Padrob's (%2); open it with a newer Padrob (it was left untouched)</source>
        <translation>tiene la versión de esquema %1, más nueva que la de este Padrob (%2); ábrala con un Padrob más nuevo (no se modificó)</translation>
    </message>
    <message>
        <location line="+14" />
        <source>it holds no records yet, and it is open read-only</source>
        <translation>aún no contiene registros, y está abierta en solo lectura</translation>
    </message>
    <message>
        <location line="+1" />
        <source>it has the older schema version %1 and this Padrob needs %2; open it once with write access to upgrade it</source>
        <translation>tiene la versión de esquema anterior %1 y este Padrob necesita la %2; ábrala una vez con permiso de escritura para actualizarla</translation>
    </message>
    <message>
        <location line="+14" />
        <source>SQLite refused the write-ahead log (journal mode %1)</source>
        <translation>SQLite rechazó el registro de escritura anticipada (modo de diario %1)</translation>
    </message>
    <message>
        <location line="+37" />
        <source>the upgrade to schema version %1 failed (%2)</source>
        <translation>falló la actualización a la versión de esquema %1 (%2)</translation>
    </message>
    <message>
        <location line="+224" />
        <location line="+470" />
        <source>cannot add the operator “%1”</source>
        <translation>no se puede agregar al operador “%1”</translation>
    </message>
    <message>
        <location line="-468" />
        <location line="+470" />
        <source>an operator needs an id</source>
        <translation>un operador necesita un id</translation>
    </message>
    <message>
        <location line="-464" />
        <source>the id is taken already, by “%1”</source>
        <translation>el id ya está en uso, por “%1”</translation>
    </message>
    <message>
        <location line="+14" />
        <source>cannot rename the operator</source>
        <translation>no se puede cambiar el nombre del operador</translation>
    </message>
    <message>
        <location line="+7" />
        <location line="+31" />
        <source>there is no operator %1</source>
        <translation>no existe el operador %1</translation>
    </message>
    <message>
        <location line="-25" />
        <source>cannot look the operator up</source>
        <translation>no se puede buscar al operador</translation>
    </message>
    <message>
        <location line="+15" />
        <source>cannot record the start of the attempt</source>
        <translation>no se puede registrar el inicio del intento</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the tutorial has no id</source>
        <translation>el tutorial no tiene id</translation>
    </message>
    <message>
        <location line="+33" />
        <source>cannot record the attempt's events</source>
        <translation>no se pueden registrar los eventos del intento</translation>
    </message>
    <message>
        <location line="+4" />
        <source>an event has no valid time</source>
        <translation>un evento no tiene un tiempo válido</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+54" />
        <location line="+275" />
        <source>there is no attempt %1</source>
        <translation>no existe el intento %1</translation>
    </message>
    <message>
        <location line="-300" />
        <source>cannot record the attempt's result</source>
        <translation>no se puede registrar el resultado del intento</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the score %1 is not within 0…100</source>
        <translation>el puntaje %1 no está entre 0…100</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 stars is not within 0…3</source>
        <translation>%1 estrellas no está entre 0…3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the duration %1 s is not valid</source>
        <translation>la duración %1 s no es válida</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the score breakdown has an empty or repeated key “%1”</source>
        <translation>el desglose del puntaje tiene una clave vacía o repetida “%1”</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the score item “%1” has no valid value or points</source>
        <translation>el ítem de puntaje “%1” no tiene un valor o puntos válidos</translation>
    </message>
    <message>
        <location line="+37" />
        <source>cannot read the operators' progress</source>
        <translation>no se puede leer el avance de los operadores</translation>
    </message>
    <message>
        <location line="+59" />
        <source>cannot read the operator's attempts</source>
        <translation>no se pueden leer los intentos del operador</translation>
    </message>
    <message>
        <location line="+7" />
        <location line="+96" />
        <location line="+82" />
        <source>cannot read the attempt</source>
        <translation>no se puede leer el intento</translation>
    </message>
    <message>
        <location line="-165" />
        <source>cannot export the records to %1</source>
        <translation>no se pueden exportar los registros a %1</translation>
    </message>
    <message>
        <location line="-191" />
        <source>there is an attempt with the id %1 already</source>
        <translation>ya hay un intento con el identificador %1</translation>
    </message>
    <message>
        <location line="+63" />
        <source>an attempt ends finished, aborted or interrupted, not %1</source>
        <translation>un intento termina finalizado, abortado o interrumpido, no %1</translation>
    </message>
    <message>
        <location line="+226" />
        <source>cannot read what the centre's server lacks</source>
        <translation>no se puede leer lo que le falta al servidor del centro</translation>
    </message>
    <message>
        <location line="+44" />
        <location line="+12" />
        <source>cannot note what the centre's server has</source>
        <translation>no se puede anotar lo que tiene el servidor del centro</translation>
    </message>
    <message>
        <location line="+22" />
        <source>cannot give the old attempts their unique ids</source>
        <translation>no se pueden dar a los intentos antiguos sus identificadores únicos</translation>
    </message>
    <message>
        <location line="+18" />
        <source>cannot read the attempt's events</source>
        <translation>no se pueden leer los eventos del intento</translation>
    </message>
    <message>
        <location line="+39" />
        <source>cannot copy the attempt %1</source>
        <translation>no se puede copiar el intento %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the attempt has no unique id</source>
        <translation>el intento no tiene identificador único</translation>
    </message>
    <message>
        <location line="+62" />
        <source>an event has no index</source>
        <translation>un evento no tiene índice</translation>
    </message>
    <message>
        <location line="+18" />
        <source>cannot reach the records database</source>
        <translation>no se puede alcanzar la base de datos de registros</translation>
    </message>
</context>
<context>
    <name>trainer::records::SharedRecords</name>
    <message>
        <location filename="../trainer/records/shared_records.cpp" line="+165" />
        <source>cannot send the records to the centre's server: the station's records are not open</source>
        <translation>no se pueden enviar los registros al servidor del centro: los registros del puesto no están abiertos</translation>
    </message>
    <message>
        <location line="+104" />
        <source>not connected yet to the centre's records server %1: this station records on its own until it is</source>
        <translation>aún sin conexión con el servidor de registros del centro %1: este puesto registra por su cuenta hasta tenerla</translation>
    </message>
    <message>
        <location line="+3" />
        <source>this station records on its own, and sends its records to the centre's server %1 when it is back (%2)</source>
        <translation>este puesto registra por su cuenta y envía sus registros al servidor del centro %1 cuando vuelva (%2)</translation>
    </message>
</context>
</TS>
