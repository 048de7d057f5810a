package tactus.export;

import java.util.ArrayList;
import java.util.List;

/**
 * The signal graph of an exported model, written the way mass-interaction models are written in Faust (as MIMS
 * does): the masses turn forces into positions, a routing function hands positions to the interactions (and to
 * the outputs), the interactions turn them into forces, and a second routing function sums the forces of each
 * mass (with the external inputs) and feeds them back through Faust's one-sample recursion {@code ~}, which is
 * the scheme's one-step force delay.
 *
 * <pre>
 * model = (toMasses : masses : toLinks : (links, si.bus(outputs))) ~ si.bus(linkForces)
 *       : (si.block(linkForces), si.bus(outputs));
 * </pre>
 */
final class Network {
    private final List<String> massBlocks = new ArrayList<>();
    private int positions;
    private final List<List<String>> portTerms = new ArrayList<>();
    private final List<String> linkBlocks = new ArrayList<>();
    private final List<Integer> linkInputs = new ArrayList<>();
    private int linkOutputs;
    private final List<String> outputs = new ArrayList<>();
    private int inputs;

    /** Adds a mass block with the given number of position outputs; @return the index of its first position. */
    int addMass(String block, int outputsOfBlock) {
        massBlocks.add(wrapped(block));
        int base = positions;
        positions += outputsOfBlock;
        return base;
    }

    /** Adds a force port: one input of the mass blocks, in order; @return its index. */
    int addPort() {
        portTerms.add(new ArrayList<>());
        return portTerms.size() - 1;
    }

    /**
     * Adds an interaction block.
     *
     * @param in the position signals it reads, in its input order
     * @param out for each of its outputs, the force port it adds to, or -1 for a force nobody takes
     */
    void addLink(String block, int[] in, int[] out) {
        linkBlocks.add(wrapped(block));
        for (int p : in) {
            linkInputs.add(p);
        }
        for (int port : out) {
            if (port >= 0) {
                portTerms.get(port).add("l" + linkOutputs);
            }
            linkOutputs++;
        }
    }

    /** Adds an output of the program: an expression of position names {@link #pos(int)}. */
    void addOutput(String expression) {
        outputs.add(expression);
    }

    /** Adds an input of the program, scaled, to a force port (-1: an input that acts on nothing). */
    void addInput(int port, double scale) {
        String in = "in" + inputs++;
        if (port < 0) {
            return;
        }
        portTerms.get(port).add(scale == 1 ? in : in + "*" + FaustNumbers.lit(scale));
    }

    /** Adds a force that acts at the first sample only (a force pending in the model at export). */
    void addPending(int port, double force) {
        if (force != 0) {
            portTerms.get(port).add(FaustNumbers.lit(force) + "*i0");
        }
    }

    /** @return the name of a position signal inside {@code toLinks} */
    static String pos(int p) {
        return "p" + p;
    }

    int outputCount() {
        return outputs.size();
    }

    /** Writes the definitions of masses, links, routings and {@code model}. */
    void write(StringBuilder out) {
        out.append("// ").append(massBlocks.size()).append(" masses: forces in, positions out\n");
        out.append("masses = ").append(par(massBlocks, "\n  ")).append(";\n\n");
        if (!linkBlocks.isEmpty()) {
            out.append("// ").append(linkBlocks.size()).append(" interactions: positions in, forces out\n");
            out.append("links = ").append(par(linkBlocks, "\n  ")).append(";\n\n");
        }
        out.append("// positions to interactions, then the outputs\n");
        List<String> toLinks = new ArrayList<>();
        for (int p : linkInputs) {
            toLinks.add(pos(p));
        }
        toLinks.addAll(outputs);
        out.append("toLinks(");
        for (int p = 0; p < positions; p++) {
            out.append(p == 0 ? "" : ", ").append(pos(p));
            if (p % 16 == 15) {
                out.append("\n  ");
            }
        }
        out.append(") = ").append(lines(toLinks)).append(";\n\n");
        boolean ported = !portTerms.isEmpty();
        if (ported) {
            out.append("// forces of the interactions (and inputs) to the masses\n");
            List<String> params = new ArrayList<>();
            for (int l = 0; l < linkOutputs; l++) {
                params.add("l" + l);
            }
            for (int i = 0; i < inputs; i++) {
                params.add("in" + i);
            }
            List<String> sums = new ArrayList<>();
            for (List<String> terms : portTerms) {
                sums.add(terms.isEmpty() ? "0.0" : String.join(" + ", terms));
            }
            out.append("toMasses");
            if (!params.isEmpty()) {
                out.append('(').append(lines(params)).append(')');
            }
            out.append(" = ").append(lines(sums)).append(";\n\n");
        }
        String chain = (ported ? "toMasses : " : "") + "masses : toLinks";
        if (linkBlocks.isEmpty()) {
            out.append("model = ").append(chain).append(";\n");
        } else if (!ported) {
            out.append("model = ").append(chain).append(" : (links, si.bus(").append(outputs.size())
                    .append(")) : (si.block(").append(linkOutputs).append("), si.bus(").append(outputs.size())
                    .append("));\n");
        } else {
            out.append("model = (").append(chain).append(" : (links, si.bus(").append(outputs.size()).append(")))")
                    .append(" ~ si.bus(").append(linkOutputs).append(")\n  : (si.block(").append(linkOutputs)
                    .append("), si.bus(").append(outputs.size()).append("));\n");
        }
    }

    /** @return the block in brackets when it is a composition, so that a parallel list of blocks parses right */
    private static String wrapped(String block) {
        return block.indexOf(':') >= 0 || block.indexOf('~') >= 0 ? "(" + block + ")" : block;
    }

    private static String par(List<String> blocks, String sep) {
        return String.join("," + sep, blocks);
    }

    private static String lines(List<String> items) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < items.size(); i++) {
            if (i > 0) {
                b.append(i % 16 == 0 ? ",\n  " : ", ");
            }
            b.append(items.get(i));
        }
        return b.toString();
    }
}
