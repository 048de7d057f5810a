package tactus.export;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;

import tactus.PhysicalModel;

/**
 * Writes a model as a Faust program ({@code .dsp}) that computes, sample for sample, what Tactus computes
 * stepping the same model: one Faust sample is one simulation step, so the program sounds as the model does in
 * Tactus when it runs at the model's simulation rate ({@link PhysicalModel#getSimRate()}).
 *
 * <p>The model is written as it is now: each mass starts from its current and previous positions (so its
 * velocity carries over), the forces that the last interaction phase left for the next step act on the first
 * sample, and every parameter is written as its per-step value (in REAL_UNITS: stiffness K/fs², damping Z/fs,
 * gravity g/fs², forces F/fs²). A 1-D model (only {@code Mass1D}, {@code Osc1D}, {@code Ground1D},
 * {@code SpringDamper1D}, {@code Contact3D} between masses on one vertical line and {@code PlaneContact3D}) is
 * written with {@code mi.lib}'s primitives; any other model as the explicit scheme in plain Faust. What the
 * program outputs, where it takes forces in and its sliders come from {@link FaustExportOptions}.
 *
 * <pre>
 * FaustExporter.write(mdl, new FaustExportOptions().listen("m12", 2, 100).forceInput("m3", 2),
 *     new File("string.dsp"));
 * // faust2jack string.dsp   (or faust2lv2, faust2wasm, ...)
 * </pre>
 *
 * <p>Refused, with a {@link FaustExportException} naming the module and why: haptic avatars
 * ({@code HapticInput3D}), position drivers ({@code PosInput3D}), masses under velocity control, contact groups,
 * and a program with no output. The export only reads the model (query by query: to export a model that a
 * {@code PhyUGen} is playing, the state is that of the moments each query ran).
 */
public final class FaustExporter {
    private FaustExporter() {
    }

    /**
     * {@return the Faust program of the model as it is now}
     * @throws FaustExportException if a module or an option cannot be exported
     */
    public static String toDsp(PhysicalModel model, FaustExportOptions options) {
        if (model == null || options == null) {
            throw new IllegalArgumentException("FaustExporter.toDsp: model and options are needed");
        }
        Scene s = Scene.read(model);
        if (s.masses.length == 0) {
            throw new FaustExportException("model", "it has no masses");
        }
        if (options.listens().isEmpty()) {
            throw new FaustExportException("options", "nothing to listen to: add listen(mass, axis)");
        }
        for (FaustExportOptions.Listen l : options.listens()) {
            requireMass(s, "listen", l.mass);
        }
        for (FaustExportOptions.Input in : options.inputs()) {
            requireMass(s, "forceInput", in.mass);
        }
        Params p = new Params(s, model, options);
        String why = MiLibWriter.whyNot(s);
        Network net = new Network();
        if (why == null) {
            MiLibWriter.build(s, p, options, net);
        } else {
            ExplicitWriter.build(s, p, options, net);
        }
        StringBuilder b = new StringBuilder();
        b.append("// ").append(options.name()).append(": exported by Tactus ").append(PhysicalModel.version())
                .append(" from a model of ").append(s.masses.length).append(" masses and ").append(s.links.length)
                .append(" interactions\n// simulated at ").append(s.fs).append(" steps per second. ")
                .append("Every parameter is per step (the scheme's own numbers):\n// run this program at ")
                .append(s.fs).append(" Hz to hear the model as in Tactus.\n");
        b.append(why == null ? "// 1-D model: mi.lib primitives.\n"
                : "// Explicit 3-D scheme (" + why + " has no mi.lib form).\n");
        b.append("declare name \"").append(options.name()).append("\";\n");
        b.append("declare tactus_sim_rate \"").append(s.fs).append("\";\n");
        b.append("import(\"stdfaust.lib\");\n\n");
        b.append("i0 = 1 - 1';   // 1 at the first sample, then 0\n\n");
        if (!p.declarations.isEmpty()) {
            b.append("// sliders, in the model's units (").append(s.real ? "REAL_UNITS" : "ALGO_UNITS").append(")\n");
            for (String d : p.declarations) {
                b.append(d).append('\n');
            }
            b.append('\n');
        }
        if (why != null) {
            b.append(ExplicitWriter.HELPERS).append('\n');
        }
        net.write(b);
        b.append("\nprocess = model;\n");
        return b.toString();
    }

    /**
     * Writes the Faust program of the model to a file (UTF-8), replacing it.
     *
     * @return the file written
     * @throws IOException if the file cannot be written
     * @throws FaustExportException if a module or an option cannot be exported
     */
    public static File write(PhysicalModel model, FaustExportOptions options, File file) throws IOException {
        String dsp = toDsp(model, options);
        Files.write(file.toPath(), dsp.getBytes(StandardCharsets.UTF_8));
        return file;
    }

    private static void requireMass(Scene s, String op, String name) {
        if (s.mass(name) < 0) {
            throw new FaustExportException(op + "(\"" + name + "\")", "no mass of that name in the model");
        }
    }
}
