package tactus.io;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Turns the XML tree of a model file into a {@link ModelFile}, checking its structure: the three
 * sections, known group names, the attributes each module type needs, numbers that parse, unique
 * mass names and consistent indices. It does not touch any model.
 */
final class ModelFileParser {
    private final String source;

    ModelFileParser(String source) {
        this.source = source;
    }

    ModelFile parse(XmlNode root) {
        ModelFile f = new ModelFile();
        readGlobal(section(root, "global"), f);
        XmlNode mat = section(root, "MAT");
        for (XmlNode group : mat.children) {
            if (!FileTypes.MASS_GROUPS.contains(group.name)) {
                throw fail(group, "unknown mass type \"" + group.name + "\"; known types: " + FileTypes.MASS_GROUPS);
            }
            for (XmlNode e : group.children) {
                f.masses.add(readMass(group.name, e));
            }
        }
        XmlNode link = section(root, "Link");
        for (XmlNode group : link.children) {
            if (!FileTypes.LINK_GROUPS.contains(group.name)) {
                throw fail(group, "unknown interaction type \"" + group.name + "\"; known types: "
                        + FileTypes.LINK_GROUPS);
            }
            for (XmlNode e : group.children) {
                f.links.add(readLink(group.name, e));
            }
        }
        restoreOrder(f.masses, "mass", s -> s.index, s -> s.element, s -> s.line);
        restoreOrder(f.links, "interaction", s -> s.index, s -> s.element, s -> s.line);
        Set<String> names = new HashSet<>();
        for (MassSpec m : f.masses) {
            if (!names.add(m.name)) {
                throw new ModelFileException(source, m.line, m.element, "mass name \"" + m.name
                        + "\" is used twice in the file", null);
            }
        }
        return f;
    }

    private XmlNode section(XmlNode root, String name) {
        XmlNode s = root.child(name);
        if (s == null) {
            throw fail(root, "the <" + name + "> section is missing");
        }
        return s;
    }

    private void readGlobal(XmlNode g, ModelFile f) {
        f.globalLine = g.line;
        f.gravity = number(part(g, "gravity"), "gravity");
        f.friction = number(part(g, "friction"), "friction");
        XmlNode v = part(g, "vector");
        f.dirX = number(v, "pos.x");
        f.dirY = number(v, "pos.y");
        f.dirZ = number(v, "pos.z");
        XmlNode u = g.child("units");
        if (u != null) {
            f.unitsLine = u.line;
            f.paramSystem = text(u, "paramSystem");
            if (!f.paramSystem.equals("ALGO_UNITS") && !f.paramSystem.equals("REAL_UNITS")) {
                throw fail(u, "paramSystem must be ALGO_UNITS or REAL_UNITS, got \"" + f.paramSystem + "\"");
            }
            if (u.attributes.containsKey("simRate")) {
                f.simRate = integer(u, "simRate");
            }
        }
    }

    private XmlNode part(XmlNode parent, String name) {
        XmlNode n = parent.child(name);
        if (n == null) {
            throw fail(parent, "the <" + name + "> element is missing");
        }
        return n;
    }

    private MassSpec readMass(String type, XmlNode e) {
        MassSpec m = new MassSpec();
        m.type = type;
        m.element = e.name;
        m.line = e.line;
        m.name = text(e, "name");
        m.index = optionalIndex(e);
        m.x = number(e, "initPos.x");
        m.y = number(e, "initPos.y");
        m.z = number(e, "initPos.z");
        if (FileTypes.isInertial(type)) {
            m.mass = number(e, "mass");
            m.vx = velocity(e, "x");
            m.vy = velocity(e, "y");
            m.vz = velocity(e, "z");
        }
        if (FileTypes.isOscillator(type)) {
            m.stiffness = number(e, "stiffness");
            m.damping = number(e, "damping");
        }
        if (FileTypes.isInput(type) && e.attributes.containsKey("smoothing")) {
            m.smoothing = integer(e, "smoothing");
        }
        return m;
    }

    private LinkSpec readLink(String type, XmlNode e) {
        LinkSpec l = new LinkSpec();
        l.type = type;
        l.element = e.name;
        l.line = e.line;
        l.name = text(e, "name");
        l.index = optionalIndex(e);
        l.m1 = text(e, "m1");
        l.m2 = FileTypes.isSingleMass(type) ? l.m1 : text(e, "m2");
        switch (type) {
            case "Damper3D":
                l.damping = number(e, "damping");
                break;
            case "Spring3D":
                l.stiffness = number(e, "stiffness");
                l.length = number(e, "drest");
                break;
            case "Attractor3D":
                l.length = number(e, "limitDist");
                l.attraction = number(e, "attrFactor");
                break;
            default:
                l.stiffness = number(e, "stiffness");
                l.damping = number(e, "damping");
                l.length = number(e, "drest");
                if (type.equals("PlaneContact3D")) {
                    l.orientation = integer(e, "orientation");
                    l.planePosition = number(e, "position");
                }
        }
        if (FileTypes.hasExtraParameters(type)) {
            String[] names = FileTypes.extraParameters(type);
            l.extra = new double[names.length];
            for (int k = 0; k < names.length; k++) {
                l.extra[k] = number(e, names[k]);
            }
        }
        return l;
    }

    /**
     * Puts the modules back in model order when the file gives indices: either every element of the
     * section has a distinct index, or none has one (then the file order is kept).
     */
    private <T> void restoreOrder(List<T> specs, String what, java.util.function.ToIntFunction<T> index,
                                  java.util.function.Function<T, String> element,
                                  java.util.function.ToIntFunction<T> line) {
        int with = 0;
        Set<Integer> seen = new HashSet<>();
        for (T s : specs) {
            int i = index.applyAsInt(s);
            if (i >= 0) {
                with++;
                if (!seen.add(i)) {
                    throw new ModelFileException(source, line.applyAsInt(s), element.apply(s),
                            "index " + i + " is used by two " + what + " elements", null);
                }
            }
        }
        if (with == 0) {
            return;
        }
        for (T s : specs) {
            if (index.applyAsInt(s) < 0) {
                throw new ModelFileException(source, line.applyAsInt(s), element.apply(s),
                        "the index attribute is missing while other " + what + " elements have one", null);
            }
        }
        List<T> sorted = new ArrayList<>(specs);
        sorted.sort(Comparator.comparingInt(index));
        specs.clear();
        specs.addAll(sorted);
    }

    private int optionalIndex(XmlNode e) {
        if (!e.attributes.containsKey("index")) {
            return -1;
        }
        int i = integer(e, "index");
        if (i < 0) {
            throw fail(e, "index must be >= 0, got " + i);
        }
        return i;
    }

    private String text(XmlNode e, String attr) {
        String v = e.attributes.get(attr);
        if (v == null || v.isEmpty()) {
            throw fail(e, "the attribute \"" + attr + "\" is missing or empty");
        }
        return v;
    }

    private double number(XmlNode e, String attr) {
        String v = text(e, attr);
        try {
            return Double.parseDouble(v.trim());
        } catch (NumberFormatException x) {
            throw fail(e, "the attribute \"" + attr + "\" must be a number, got \"" + v + "\"");
        }
    }

    /**
     * @return one coordinate of a mass's initial velocity, in units per second: {@code initVel.*} (what the
     *     paper-era engine writes and reads, from v1.1.1 on), else {@code posR.*} (its first loader, and Tactus
     *     before it read initVel), else 0. When both are given they must agree.
     */
    private double velocity(XmlNode e, String axis) {
        String paper = "initVel." + axis;
        String early = "posR." + axis;
        boolean hasPaper = e.attributes.containsKey(paper);
        if (hasPaper && e.attributes.containsKey(early)) {
            double a = number(e, paper);
            double b = number(e, early);
            if (Double.compare(a, b) != 0) {
                throw fail(e, "the attributes \"" + paper + "\" (" + a + ") and \"" + early + "\" (" + b
                        + ") give two different velocities; keep one of them");
            }
            return a;
        }
        return optionalNumber(e, hasPaper ? paper : early);
    }

    private double optionalNumber(XmlNode e, String attr) {
        return e.attributes.containsKey(attr) ? number(e, attr) : 0;
    }

    private int integer(XmlNode e, String attr) {
        String v = text(e, attr);
        try {
            return Integer.parseInt(v.trim());
        } catch (NumberFormatException x) {
            throw fail(e, "the attribute \"" + attr + "\" must be an integer, got \"" + v + "\"");
        }
    }

    private ModelFileException fail(XmlNode e, String message) {
        return new ModelFileException(source, e.line, e.name, message, null);
    }
}
