package tactus.io;

import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import javax.xml.stream.XMLOutputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamWriter;

/**
 * Writes a {@link ModelFile} in the layout of the paper's engine: a root element, then
 * {@code <global>}, {@code <MAT>} with one group per mass type and {@code <Link>} with one group per
 * interaction type, every group present even when empty, each module named {@code mass_<index>} or
 * {@code interaction_<index>} with its attributes in alphabetical order, indented by two spaces (the
 * paper's loader counts on the whitespace between elements). Numbers are written with
 * {@link Double#toString(double)}, which reads back to the same double.
 */
final class ModelFileWriter {
    private final XMLStreamWriter out;
    private int depth;

    private ModelFileWriter(XMLStreamWriter out) {
        this.out = out;
    }

    static void write(ModelFile f, String rootName, Writer target) throws XMLStreamException {
        XMLStreamWriter w = XMLOutputFactory.newFactory().createXMLStreamWriter(target);
        new ModelFileWriter(w).document(f, rootName);
        w.flush();
    }

    private void document(ModelFile f, String rootName) throws XMLStreamException {
        out.writeStartDocument("UTF-8", "1.0");
        open(rootName);
        open("global");
        leaf("gravity", "gravity", num(f.gravity));
        leaf("friction", "friction", num(f.friction));
        leaf("vector", "pos.x", num(f.dirX), "pos.y", num(f.dirY), "pos.z", num(f.dirZ));
        leaf("units", "paramSystem", f.paramSystem, "simRate", Integer.toString(f.simRate));
        close();
        open("MAT");
        for (String type : FileTypes.MASS_GROUPS) {
            List<String[]> members = new ArrayList<>();
            for (MassSpec m : f.masses) {
                if (m.type.equals(type)) {
                    members.add(massAttributes(m));
                }
            }
            group(type, "mass_", members);
        }
        close();
        open("Link");
        for (String type : FileTypes.LINK_GROUPS) {
            List<String[]> members = new ArrayList<>();
            for (LinkSpec l : f.links) {
                if (l.type.equals(type)) {
                    members.add(linkAttributes(l));
                }
            }
            group(type, "interaction_", members);
        }
        close();
        close();
        out.writeCharacters("\n");
        out.writeEndDocument();
    }

    /** @return index then alternating attribute names and values, names in alphabetical order. */
    private static String[] massAttributes(MassSpec m) {
        List<String> a = new ArrayList<>();
        a.add(Integer.toString(m.index));
        boolean inertial = FileTypes.isInertial(m.type);
        boolean osc = FileTypes.isOscillator(m.type);
        if (osc) {
            add(a, "damping", num(m.damping));
        }
        add(a, "index", Integer.toString(m.index));
        add(a, "initPos.x", num(m.x));
        add(a, "initPos.y", num(m.y));
        add(a, "initPos.z", num(m.z));
        if (inertial) {
            // the paper-era engine's name for the velocity (v1.1.1 to the paper's commit); it reads no other
            add(a, "initVel.x", num(m.vx));
            add(a, "initVel.y", num(m.vy));
            add(a, "initVel.z", num(m.vz));
            add(a, "mass", num(m.mass));
        }
        add(a, "name", m.name);
        if (osc) {
            add(a, "stiffness", num(m.stiffness));
        }
        return a.toArray(new String[0]);
    }

    private static String[] linkAttributes(LinkSpec l) {
        List<String> a = new ArrayList<>();
        a.add(Integer.toString(l.index));
        if (l.type.equals("Attractor3D")) {
            add(a, "attrFactor", num(l.attraction));
            add(a, "index", Integer.toString(l.index));
            add(a, "limitDist", num(l.length));
            add(a, "m1", l.m1);
            add(a, "m2", l.m2);
            add(a, "name", l.name);
            return a.toArray(new String[0]);
        }
        boolean spring = l.type.equals("Spring3D");
        boolean plane = l.type.equals("PlaneContact3D");
        if (!spring) {
            add(a, "damping", num(l.damping));
        }
        add(a, "drest", num(l.length));
        add(a, "index", Integer.toString(l.index));
        add(a, "m1", l.m1);
        add(a, "m2", l.m2);
        add(a, "name", l.name);
        if (FileTypes.hasExtraParameters(l.type)) {
            String[] names = FileTypes.extraParameters(l.type);
            for (int k = 0; k < names.length; k++) {
                add(a, names[k], num(l.extra[k]));
            }
        }
        if (plane) {
            add(a, "orientation", Integer.toString(l.orientation));
            add(a, "position", num(l.planePosition));
        }
        add(a, "stiffness", num(l.stiffness));
        return a.toArray(new String[0]);
    }

    private static void add(List<String> a, String name, String value) {
        a.add(name);
        a.add(value);
    }

    private static String num(double v) {
        return Double.toString(v);
    }

    private void group(String type, String prefix, List<String[]> members) throws XMLStreamException {
        if (members.isEmpty()) {
            indent();
            out.writeEmptyElement(type);
            return;
        }
        open(type);
        for (String[] m : members) {
            indent();
            out.writeEmptyElement(prefix + m[0]);
            for (int i = 1; i < m.length; i += 2) {
                out.writeAttribute(m[i], m[i + 1]);
            }
        }
        close();
    }

    private void open(String name) throws XMLStreamException {
        indent();
        out.writeStartElement(name);
        depth++;
    }

    private void close() throws XMLStreamException {
        depth--;
        indent();
        out.writeEndElement();
    }

    private void leaf(String name, String... attributes) throws XMLStreamException {
        indent();
        out.writeEmptyElement(name);
        for (int i = 0; i < attributes.length; i += 2) {
            out.writeAttribute(attributes[i], attributes[i + 1]);
        }
    }

    private void indent() throws XMLStreamException {
        StringBuilder b = new StringBuilder("\n");
        for (int i = 0; i < depth; i++) {
            b.append("  ");
        }
        out.writeCharacters(b.toString());
    }
}
