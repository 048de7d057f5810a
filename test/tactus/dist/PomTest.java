package tactus.dist;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.util.HashMap;
import java.util.Map;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * The POM that {@code gradle publishToMavenLocal} publishes and {@code gradle release} ships (the Gradle test task
 * generates it first): coordinates io.github.tactus:tactus:&lt;version&gt;, the project data Maven Central requires
 * (name, description, url, licenses, developers, scm), jSerialComm and jackson-core at runtime scope, Processing core
 * and Minim provided and optional (an application that draws or plays sound adds them itself), and nothing of the
 * tests or tools.
 */
class PomTest {
    private static String text(Element parent, String tag) {
        NodeList l = parent.getElementsByTagName(tag);
        return l.getLength() == 0 ? null : l.item(0).getTextContent().trim();
    }

    private static Element child(Element parent, String tag) {
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element && ((Element) n).getTagName().equals(tag)) {
                return (Element) n;
            }
        }
        return null;
    }

    @Test
    void thePomNamesTheRightCoordinatesAndScopes() throws Exception {
        String path = System.getProperty("tactus.dist.pom");
        if (path == null) {
            fail("run through 'gradle test', which generates the POM first and sets tactus.dist.pom");
        }
        File pom = new File(path);
        assertTrue(pom.isFile(), "no POM at " + pom);
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        Document doc = f.newDocumentBuilder().parse(pom);
        Element project = doc.getDocumentElement();
        assertEquals("io.github.tactus", child(project, "groupId").getTextContent().trim(),
                "a reverse-DNS group that Maven Central accepts");
        assertEquals("tactus", child(project, "artifactId").getTextContent().trim());
        assertEquals(System.getProperty("tactus.dist.prettyVersion"), child(project, "version").getTextContent().trim());
        assertEquals("Tactus", child(project, "name").getTextContent().trim());
        String description = child(project, "description").getTextContent().trim();
        assertTrue(description.length() > 20, "a description: " + description);
        String url = child(project, "url").getTextContent().trim();
        assertTrue(url.matches("https://\\S+"), "url: " + url);
        Element license = child(child(project, "licenses"), "license");
        assertNotNull(license, "a license");
        assertEquals("LGPL-2.1-or-later", text(license, "name"), "the SPDX identifier of the LICENSE file's licence");
        assertTrue(text(license, "url").contains("lgpl-2.1"), text(license, "url"));
        Element developer = child(child(project, "developers"), "developer");
        assertNotNull(developer, "a developer");
        assertFalse(text(developer, "name").isEmpty());
        Element scm = child(project, "scm");
        assertNotNull(scm, "an scm section");
        assertEquals("scm:git:" + url + ".git", text(scm, "connection"));
        assertEquals(url, text(scm, "url"));
        assertEquals("v" + System.getProperty("tactus.dist.prettyVersion"), text(scm, "tag"), "the release tag");

        Map<String, Element> deps = new HashMap<>();
        NodeList list = child(project, "dependencies").getElementsByTagName("dependency");
        for (int i = 0; i < list.getLength(); i++) {
            Element d = (Element) list.item(i);
            deps.put(text(d, "groupId") + ":" + text(d, "artifactId"), d);
        }
        Element serial = deps.get("com.fazecast:jSerialComm");
        assertNotNull(serial, "jSerialComm is needed at run time: " + deps.keySet());
        assertEquals("runtime", text(serial, "scope"));
        Element json = deps.get("com.fasterxml.jackson.core:jackson-core");
        assertNotNull(json, "jackson-core (the Inverse Service client's JSON) is needed at run time: " + deps.keySet());
        assertEquals("runtime", text(json, "scope"));
        for (String provided : new String[] {"org.processing:core", "net.compartmental.code:minim"}) {
            Element d = deps.get(provided);
            assertNotNull(d, provided + " must be listed (provided, optional): " + deps.keySet());
            assertEquals("provided", text(d, "scope"), provided);
            assertEquals("true", text(d, "optional"), provided);
        }
        for (String key : deps.keySet()) {
            assertFalse(key.contains("junit") || key.contains("jfreechart") || key.contains("preprocessor"),
                    "a test or tools dependency leaked into the POM: " + key);
        }
        assertEquals(4, deps.size(), "exactly jSerialComm, jackson-core, core and Minim: " + deps.keySet());
    }
}
