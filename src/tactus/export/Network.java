package tactus.export;

import java.util.ArrayList;
import java.util.List;

/**
 * The signal graph of an exported model, written the way mass-interaction models are written in Faust: the
 * masses turn forces into positions, a routing hands positions to the interactions (and to the outputs), the
 * interactions turn them into forces, and a second routing sums the forces of each mass (with the external
 * inputs) and feeds them back through Faust's one-sample recursion {@code ~}, which is the scheme's one-step
 * force delay.
 *
 * <pre>
 * model = (toMasses : masses : toLinks : (links, si.bus(outputs))) ~ si.bus(linkForces)
 *       : (si.block(linkForces), si.bus(outputs));
 * </pre>
 *
 * Both routings are one Faust {@code route} primitive each (route sums the inputs that go to the same output).
 * Routing functions with one named parameter per signal, as MIMS writes them, make {@code faust} itself slow and
 * hungry: 18 s and 1.4 GB for a 1-D string of 200 masses, 85 s and 9.3 GB for 400 (measured, docs/faust.md).
 */
final class Network {
    private final List<String> massBlocks = new ArrayList<>();
    private int positions;
    /** Per force port: link outputs (index) and inputs (-1 - index) that add to it. */
    private final List<List<Integer>> portSources = new ArrayList<>();
    private final List<Double> pending = new ArrayList<>();
    private final List<String> linkBlocks = new ArrayList<>();
    private final List<Integer> linkInputs = new ArrayList<>();
    private int linkOutputs;
    /** Per output: its position signal (-1: a constant 0), origin and gain. */
    private final List<Integer> outPosition = new ArrayList<>();
    private final List<double[]> outScale = new ArrayList<>();
    private final List<Double> inputScale = new ArrayList<>();

    /** Adds a mass block with the given number of position outputs; @return the index of its first position. */
    int addMass(String block, int outputsOfBlock) {
        massBlocks.add(wrapped(block));
        int base = positions;
        positions += outputsOfBlock;
        return base;
    }

    /** Adds a force port: one input of the mass blocks, in order; @return its index. */
    int addPort() {
        portSources.add(new ArrayList<>());
        pending.add(0.0);
        return portSources.size() - 1;
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
                portSources.get(port).add(linkOutputs);
            }
            linkOutputs++;
        }
    }

    /** Adds an output of the program: gain times (position signal minus origin); position -1 gives 0. */
    void addOutput(int position, double origin, double gain) {
        outPosition.add(position);
        outScale.add(new double[] {origin, gain});
    }

    /** Adds an input of the program, scaled, to a force port (-1: an input that acts on nothing). */
    void addInput(int port, double scale) {
        inputScale.add(scale);
        if (port >= 0) {
            portSources.get(port).add(-inputScale.size());
        }
    }

    /** Adds a force that acts at the first sample only (a force pending in the model at export). */
    void addPending(int port, double force) {
        pending.set(port, pending.get(port) + force);
    }

    int outputCount() {
        return outPosition.size();
    }

    /** Writes the definitions of masses, links, routings and {@code model}. */
    void write(StringBuilder out) {
        int outputs = outPosition.size();
        int inputs = inputScale.size();
        out.append("// ").append(massBlocks.size()).append(" masses: forces in, positions out\n");
        out.append("masses = ").append(balanced(massBlocks, 0, massBlocks.size())).append(";\n\n");
        if (!linkBlocks.isEmpty()) {
            out.append("// ").append(linkBlocks.size()).append(" interactions: positions in, forces out\n");
            out.append("links = ").append(balanced(linkBlocks, 0, linkBlocks.size())).append(";\n\n");
        }
        out.append("// positions to interactions, then the outputs (route(ins, outs, (from, to), ...), from 1)\n");
        List<String> pairs = new ArrayList<>();
        int k = 0;
        for (int p : linkInputs) {
            pair(pairs, p + 1, ++k);
        }
        List<String> taps = new ArrayList<>();
        for (int o = 0; o < outputs; o++) {
            k++;
            int p = outPosition.get(o);
            double origin = outScale.get(o)[0];
            double gain = outScale.get(o)[1];
            if (p >= 0) {
                pair(pairs, p + 1, k);
            }
            String tap = origin == 0 || p < 0 ? "_" : "-(" + FaustNumbers.lit(origin) + ")";
            if (gain != 1 && p >= 0) {
                tap = tap.equals("_") ? "*(" + FaustNumbers.lit(gain) + ")" : tap + " : *(" + FaustNumbers.lit(gain)
                        + ")";
            }
            taps.add(tap.contains(":") ? "(" + tap + ")" : tap);
        }
        out.append("toLinks = ").append(route(positions, k, pairs));
        if (taps.stream().anyMatch(t -> !t.equals("_"))) {
            out.append("\n  : (").append(linkInputs.isEmpty() ? "" : "si.bus(" + linkInputs.size() + "), ")
                    .append(String.join(", ", taps)).append(")");
        }
        out.append(";\n\n");
        boolean ported = !portSources.isEmpty();
        if (ported) {
            out.append("// forces of the interactions (then the inputs) to the masses: route sums them\n");
            List<String> fp = new ArrayList<>();
            List<String> first = new ArrayList<>();
            boolean anyPending = false;
            for (int port = 0; port < portSources.size(); port++) {
                for (int src : portSources.get(port)) {
                    pair(fp, src >= 0 ? src + 1 : linkOutputs - src, port + 1);
                }
                double f = pending.get(port);
                first.add(f == 0 ? "_" : "+(" + FaustNumbers.lit(f) + "*i0)");
                anyPending |= f != 0;
            }
            out.append("toMasses = ");
            if (inputs > 0 && inputScale.stream().anyMatch(x -> x != 1)) {
                List<String> scales = new ArrayList<>();
                for (double x : inputScale) {
                    scales.add(x == 1 ? "_" : "*(" + FaustNumbers.lit(x) + ")");
                }
                out.append("(").append(linkOutputs > 0 ? "si.bus(" + linkOutputs + "), " : "")
                        .append(String.join(", ", scales)).append(") : ");
            }
            out.append(route(linkOutputs + inputs, portSources.size(), fp));
            if (anyPending) {
                out.append("\n  // forces pending in the model at export act on the first sample\n  : (")
                        .append(lines(first)).append(")");
            }
            out.append(";\n\n");
        }
        String chain = (ported ? "toMasses : " : "") + "masses : toLinks";
        if (linkBlocks.isEmpty()) {
            out.append("model = ").append(chain).append(";\n");
        } else if (!ported) {
            out.append("model = ").append(chain).append(" : (links, si.bus(").append(outputs)
                    .append(")) : (si.block(").append(linkOutputs).append("), si.bus(").append(outputs)
                    .append("));\n");
        } else {
            out.append("model = (").append(chain).append(" : (links, si.bus(").append(outputs).append(")))")
                    .append(" ~ si.bus(").append(linkOutputs).append(")\n  : (si.block(").append(linkOutputs)
                    .append("), si.bus(").append(outputs).append("));\n");
        }
    }

    /**
     * @return the blocks [from, to) in parallel, bracketed as a balanced tree of groups of at most 64: faust reads
     *     {@code a, b, c, ...} as a chain nested one level per block, and its evaluator overflows its stack at a
     *     few thousand
     */
    private static String balanced(List<String> blocks, int from, int to) {
        return balanced(blocks, from, to, ",\n  ");
    }

    private static String balanced(List<String> blocks, int from, int to, String sep) {
        if (to - from <= 64) {
            return String.join(sep, blocks.subList(from, to));
        }
        int mid = (from + to) >>> 1;
        return "(" + balanced(blocks, from, mid, sep) + ")" + sep + "(" + balanced(blocks, mid, to, sep) + ")";
    }

    /** @return {@code route(ins, outs, pairs)} with the pairs as a balanced tree (a flat list of 30,000 overflows faust) */
    private static String route(int ins, int outs, List<String> pairs) {
        return "route(" + ins + ", " + outs + (pairs.isEmpty() ? "" : ", " + balanced(pairs, 0, pairs.size(), ", "))
                + ")";
    }

    private static void pair(List<String> pairs, int from, int to) {
        pairs.add("(" + from + ", " + to + ")");
    }

    /** @return the block in brackets when it is a composition, so that a parallel list of blocks parses right */
    private static String wrapped(String block) {
        return block.indexOf(':') >= 0 || block.indexOf('~') >= 0 ? "(" + block + ")" : block;
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
