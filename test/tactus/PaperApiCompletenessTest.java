package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;

/**
 * The promise of issue #11, checked by reflection: every public constructor, method, field and enum constant of
 * the paper's engine (miPhysics_Processing v1.1.x), listed by hand in {@code paper-api-v1.1.txt}, exists in
 * package {@code tactus} with the same name, parameter types and return type, or is one of the
 * {@link #DIFFERENCES documented differences}, each of which {@code docs/coming-from-miphysics.md} mentions.
 */
class PaperApiCompletenessTest {

    /** The list of the original's public API, a resource beside this class. */
    static final String API_LIST = "paper-api-v1.1.txt";
    /** The page that explains every difference. */
    static final Path DOC = Paths.get("docs", "coming-from-miphysics.md");

    /**
     * Signatures of the original that Tactus does not provide exactly, each with what the doc page must mention
     * (the method's name, or our signature). Everything else in the list must match.
     */
    static final Map<String, String> DIFFERENCES = new LinkedHashMap<>();

    static {
        // The adders return a handle on the new module instead of int 0 (the original never returned anything
        // else: it exits on an error). Statements compile unchanged; the doc says so under "Return values".
        for (String adder : new String[] {
            "int addMass3D(String, double, Vect3D, Vect3D)", "int addMass2DPlane(String, double, Vect3D, Vect3D)",
            "int addMass1D(String, double, Vect3D, Vect3D)", "int addMass3DSimple(String, double, Vect3D, Vect3D)",
            "int addGround3D(String, Vect3D)", "int addGround1D(String, Vect3D)",
            "int addOsc3D(String, double, double, double, Vect3D, Vect3D)",
            "int addOsc1D(String, double, double, double, Vect3D, Vect3D)",
            "int addSpring3D(String, double, double, String, String)",
            "int addSpringDamper3D(String, double, double, double, String, String)",
            "int addSpringDamper1D(String, double, double, double, String, String)",
            "int addRope3D(String, double, double, double, String, String)",
            "int addContact3D(String, double, double, double, String, String)",
            "int addBubble3D(String, double, double, double, String, String)",
            "int addDamper3D(String, double, String, String)",
            "int addPlaneContact(String, double, double, double, int, double, String)",
            "int addAttractor3D(String, double, double, String, String)"}) {
            DIFFERENCES.put(adder, adder.substring(4, adder.indexOf('(')));
        }
        // Calls whose int status (always 0, or -1 for a case that now throws) became void.
        for (String status : new String[] {
            "int removeLink(int)", "int removeLink(String)", "int removeMatAndConnectedLinks(int)",
            "int removeMatAndConnectedLinks(String)", "int createMatSubset(String)", "int createLinkSubset(String)",
            "int addMatToSubset(int, String)", "int addMatToSubset(String, String)",
            "int addLinkToSubset(int, String)", "int addLinkToSubset(String, String)"}) {
            DIFFERENCES.put(status, status.substring(4, status.indexOf('(')));
        }
        // Returns something useful instead of nothing.
        DIFFERENCES.put("void draw_physics()", "int draw_physics()");
        DIFFERENCES.put("void changeToFixedPoint(String)", "Ground3D changeToFixedPoint(String)");
    }

    // ============================================================================================== tests

    @Test
    void everyCallOfTheOriginalExistsOrIsADocumentedDifference() throws IOException {
        List<String> missing = new ArrayList<>();
        int checked = 0;
        for (Entry e : readList()) {
            checked++;
            String problem = e.findProblem();
            if (problem != null && !DIFFERENCES.containsKey(e.member)) {
                missing.add(e.className + ": " + e.member + " -- " + problem);
            }
        }
        assertTrue(checked > 200, "the list holds only " + checked + " members");
        assertTrue(missing.isEmpty(), missing.size() + " call(s) of the paper's engine are missing or differ, "
                + "and are not documented differences:\n  " + String.join("\n  ", missing));
    }

    @Test
    void everyDocumentedDifferenceIsRealListedAndExplainedInTheDocs() throws IOException {
        String doc = new String(Files.readAllBytes(DOC), StandardCharsets.UTF_8);
        Map<String, Entry> byMember = new LinkedHashMap<>();
        for (Entry e : readList()) {
            byMember.put(e.member, e);
        }
        List<String> wrong = new ArrayList<>();
        for (Map.Entry<String, String> d : DIFFERENCES.entrySet()) {
            Entry e = byMember.get(d.getKey());
            if (e == null) {
                wrong.add(d.getKey() + " is not in " + API_LIST);
                continue;
            }
            if (e.findProblem() == null) {
                wrong.add(d.getKey() + " now matches the original exactly: remove it from DIFFERENCES");
            }
            if (!doc.contains(d.getValue())) {
                wrong.add(d.getKey() + ": " + DOC + " does not mention " + d.getValue());
            }
        }
        assertTrue(wrong.isEmpty(), String.join("\n", wrong));
    }

    /** The page for people coming from the paper's engine names every listed member (its API tables). */
    @Test
    void everyListedMemberIsNamedInTheDocs() throws IOException {
        String doc = new String(Files.readAllBytes(DOC), StandardCharsets.UTF_8);
        Set<String> missing = new LinkedHashSet<>();
        for (Entry e : readList()) {
            String m = e.member.replaceFirst("^static ", "");
            String name;
            if (m.startsWith("constant ") || m.startsWith("field ")) {
                String[] parts = m.trim().split("\\s+");
                name = parts[parts.length - 1];
            } else if (m.startsWith("new(")) {
                name = e.className + "(";
            } else {
                name = m.substring(m.indexOf(' ') + 1, m.indexOf('(')).trim();
            }
            if (!java.util.regex.Pattern.compile("\\b" + java.util.regex.Pattern.quote(name)).matcher(doc).find()) {
                missing.add(e.className + ": " + name);
            }
        }
        assertTrue(missing.isEmpty(), DOC + " does not name:\n  " + String.join("\n  ", missing));
    }

    /** The checker itself must see a missing method, a wrong return type and a missing constant. */
    @Test
    void theCheckerFindsMissingMembersAndWrongReturnTypes() {
        assertEquals(null, new Entry("PhysicalModel", "int getSimRate()").findProblem());
        assertTrue(new Entry("PhysicalModel", "int noSuchCall(int)").findProblem().contains("no method"));
        assertTrue(new Entry("PhysicalModel", "double getSimRate()").findProblem().contains("returns int"));
        assertTrue(new Entry("PhysicalModel", "void computeNSteps(double)").findProblem().contains("no method"));
        assertTrue(new Entry("PhysicalModel", "static int getSimRate()").findProblem().contains("static"));
        assertTrue(new Entry("Bound", "constant MIDDLE").findProblem().contains("constant"));
        assertTrue(new Entry("ModelLoader", "new(String)").findProblem().contains("constructor"));
        assertTrue(new Entry("Vect3D", "field float x").findProblem().contains("double"));
        assertEquals(null, new Entry("PhysicalModel",
                "void getAllMatsOfType(ArrayList<PVector>, matModuleType)").findProblem());
        assertThrows(IllegalArgumentException.class, () -> new Entry("Vect3D", "garbage").findProblem());
        assertThrows(IllegalArgumentException.class, () -> new Entry("NoSuchClass", "void f()").findProblem());
    }

    /** The two calls this issue added to the facade behave as the original's. */
    @Test
    void theAddedOverloadsBehaveAsTheOriginal() {
        Vect3D a = new Vect3D(1, 2, 3);
        assertTrue(a.equals(new Vect3D(1, 2, 3)), "equal components");
        assertFalse(a.equals(new Vect3D(1, 2, 3.0000001)), "exact comparison, no tolerance");
        assertFalse(a.equals((Vect3D) null));

        PhysicalModel floatArgs = chain();
        PhysicalModel doubleArgs = chain();
        floatArgs.changeParamOfSubset(0.25f, "springs", "stiffness");
        doubleArgs.changeParamOfSubset(0.25, "springs", "stiffness");
        assertEquals(0.25, floatArgs.getLinkStiffnessAt(0), 0.0);
        assertEquals(doubleArgs.getLinkStiffnessAt(1), floatArgs.getLinkStiffnessAt(1), 0.0);
        floatArgs.changeParamOfSubset(3f, "masses", "mass");
        assertEquals(3.0, floatArgs.getMatMassAt(1), 0.0);
        assertEquals(3.0, floatArgs.getMatMassAt(2), 0.0);
        assertNotEquals(3.0, doubleArgs.getMatMassAt(1), "the other model is untouched");
        floatArgs.changeParamOfSubset(1f, "springs", "colour"); // the original printed "unknown" and did nothing
        floatArgs.setStrict(true);
        assertThrows(IllegalArgumentException.class, () -> floatArgs.changeParamOfSubset(1f, "springs", "colour"));
    }

    private static PhysicalModel chain() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D());
        m.addMass3D("m1", 1, new Vect3D(1, 0, 0), new Vect3D());
        m.addMass3D("m2", 1, new Vect3D(2, 0, 0), new Vect3D());
        m.addSpringDamper3D("s1", 1, 0.1, 0.01, "g", "m1");
        m.addSpringDamper3D("s2", 1, 0.1, 0.01, "m1", "m2");
        m.createLinkSubset("springs");
        m.addLinkToSubset("s1", "springs");
        m.addLinkToSubset("s2", "springs");
        m.createMatSubset("masses");
        m.addMatToSubset("m1", "masses");
        m.addMatToSubset("m2", "masses");
        m.init();
        return m;
    }

    // ======================================================================================= the checker

    static List<Entry> readList() throws IOException {
        String text;
        try (InputStream in = PaperApiCompletenessTest.class.getResourceAsStream(API_LIST)) {
            if (in != null) {
                text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            } else {
                text = new String(Files.readAllBytes(Paths.get("test", "tactus", API_LIST)), StandardCharsets.UTF_8);
            }
        }
        List<Entry> entries = new ArrayList<>();
        Set<String> seen = new LinkedHashSet<>();
        String cls = null;
        for (String raw : text.split("\n")) {
            String line = raw.trim();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            if (line.startsWith("[") && line.endsWith("]")) {
                cls = line.substring(1, line.length() - 1);
                continue;
            }
            if (cls == null) {
                throw new IllegalArgumentException("member before any [Class] line: " + line);
            }
            if (!seen.add(cls + " " + line)) {
                throw new IllegalArgumentException("listed twice: " + cls + " " + line);
            }
            entries.add(new Entry(cls, line));
        }
        return entries;
    }

    /** One listed member of one class. */
    static final class Entry {
        final String className;
        final String member;

        Entry(String className, String member) {
            this.className = className;
            this.member = member;
        }

        /** @return null if Tactus has the member exactly, else what is wrong */
        String findProblem() {
            Class<?> cls = type(className);
            String m = member;
            boolean isStatic = m.startsWith("static ");
            if (isStatic) {
                m = m.substring("static ".length());
            }
            if (m.startsWith("constant ")) {
                String name = m.substring("constant ".length()).trim();
                if (!cls.isEnum()) {
                    return className + " is not an enum";
                }
                for (Object c : cls.getEnumConstants()) {
                    if (((Enum<?>) c).name().equals(name)) {
                        return null;
                    }
                }
                return "no constant " + name;
            }
            if (m.startsWith("field ")) {
                String[] parts = m.substring("field ".length()).trim().split("\\s+");
                try {
                    Field f = cls.getField(parts[1]);
                    if (f.getType() != type(parts[0])) {
                        return "the field is " + f.getType().getSimpleName() + ", not " + parts[0];
                    }
                    return staticProblem(f.getModifiers(), isStatic);
                } catch (NoSuchFieldException e) {
                    return "no public field " + parts[1];
                }
            }
            int open = m.indexOf('(');
            if (open < 0 || !m.endsWith(")")) {
                throw new IllegalArgumentException("not a member: " + member);
            }
            Class<?>[] params = params(m.substring(open + 1, m.length() - 1));
            String head = m.substring(0, open).trim();
            if (head.equals("new")) {
                try {
                    Constructor<?> c = cls.getConstructor(params);
                    return Modifier.isPublic(c.getModifiers()) ? null : "the constructor is not public";
                } catch (NoSuchMethodException e) {
                    return "no public constructor " + m;
                }
            }
            String[] rn = head.split("\\s+");
            if (rn.length != 2) {
                throw new IllegalArgumentException("not a member: " + member);
            }
            Method method;
            try {
                method = cls.getMethod(rn[1], params);
            } catch (NoSuchMethodException e) {
                return "no method " + rn[1] + " with these parameters";
            }
            Class<?> ret = type(rn[0]);
            if (method.getReturnType() != ret) {
                return "returns " + method.getReturnType().getSimpleName() + ", not " + rn[0];
            }
            return staticProblem(method.getModifiers(), isStatic);
        }

        private static String staticProblem(int modifiers, boolean wantStatic) {
            if (Modifier.isStatic(modifiers) != wantStatic) {
                return wantStatic ? "is not static" : "is static";
            }
            return null;
        }

        private static Class<?>[] params(String list) {
            if (list.trim().isEmpty()) {
                return new Class<?>[0];
            }
            // Split on commas outside angle brackets (ArrayList<PVector> has none, but stay safe).
            List<Class<?>> out = new ArrayList<>();
            int depth = 0;
            int start = 0;
            for (int i = 0; i <= list.length(); i++) {
                char c = i < list.length() ? list.charAt(i) : ',';
                if (c == '<') {
                    depth++;
                } else if (c == '>') {
                    depth--;
                } else if (c == ',' && depth == 0) {
                    out.add(type(list.substring(start, i).trim()));
                    start = i + 1;
                }
            }
            return out.toArray(new Class<?>[0]);
        }

        static Class<?> type(String simple) {
            String s = simple.replaceAll("<.*>", "").trim();
            switch (s) {
                case "void": return void.class;
                case "int": return int.class;
                case "float": return float.class;
                case "double": return double.class;
                case "boolean": return boolean.class;
                case "String": return String.class;
                case "PVector": return processing.core.PVector.class;
                case "PApplet": return processing.core.PApplet.class;
                case "ArrayList": return java.util.ArrayList.class;
                case "Lock": return java.util.concurrent.locks.Lock.class;
                default:
                    if (!s.matches("[A-Za-z][A-Za-z0-9]*")) {
                        throw new IllegalArgumentException("not a type: '" + simple + "'");
                    }
                    try {
                        return Class.forName("tactus." + s);
                    } catch (ClassNotFoundException e) {
                        throw new IllegalArgumentException("no class tactus." + s, e);
                    }
            }
        }
    }
}
