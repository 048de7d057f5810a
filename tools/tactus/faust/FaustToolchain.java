package tactus.faust;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Compiles exported Faust programs with the Debian {@code faust} and {@code g++} against Tactus's offline
 * architecture ({@code offline.cpp}, next to this class) and runs them. Every external process is bounded in
 * time. Used by the export tests and by {@link FaustCost}.
 */
public final class FaustToolchain {
    /** What to install when a tool is missing. */
    public static final String INSTALL = "apt-get install faust g++";

    /** A compiled program and what compiling it took. */
    public static final class Program {
        /** The executable. */
        public final Path executable;
        /** Wall-clock milliseconds taken by faust, and by g++ after it. */
        public final long faustMillis;
        /** Wall-clock milliseconds taken by g++. */
        public final long gccMillis;

        Program(Path executable, long faustMillis, long gccMillis) {
            this.executable = executable;
            this.faustMillis = faustMillis;
            this.gccMillis = gccMillis;
        }
    }

    /** When above 0, faust runs with its address space limited to this many kilobytes (ulimit -v). */
    private static volatile long faustMemoryKb;

    private FaustToolchain() {
    }

    /** Limits the memory of later faust runs (kilobytes of address space, 0 for no limit): large models need tens of GB. */
    public static void limitFaustMemory(long kilobytes) {
        faustMemoryKb = kilobytes;
    }

    /** Fails, naming the packages to install, unless {@code faust} and {@code g++} run. */
    public static void requireTools() {
        requireTools("faust", "g++");
    }

    /** Fails, naming the packages to install, unless every one of these commands runs with {@code --version}. */
    static void requireTools(String... tools) {
        for (String tool : tools) {
            try {
                run(List.of(tool, "--version"), null, 20, null);
            } catch (IOException | IllegalStateException e) {
                throw new IllegalStateException("the Faust export tests need " + tool + ", which does not run ("
                        + e.getMessage() + "); install it: " + INSTALL, e);
            }
        }
    }

    /**
     * Compiles a program.
     *
     * @param dsp the Faust source
     * @param dir a directory to work in
     * @param name file name stem
     * @param doublePrecision true for {@code faust -double}, false for Faust's default single precision
     * @param gccOptimisation for example "-O1" or "-O3"
     * @param timeoutSeconds bound on each of the two compilers
     */
    public static Program compile(String dsp, Path dir, String name, boolean doublePrecision, String gccOptimisation,
                                  int timeoutSeconds) throws IOException {
        Files.createDirectories(dir);
        Path arch = dir.resolve("tactus-offline.cpp");
        if (!Files.exists(arch)) {
            try (InputStream in = FaustToolchain.class.getResourceAsStream("offline.cpp")) {
                if (in == null) {
                    throw new IOException("offline.cpp is not on the class path next to FaustToolchain");
                }
                Files.copy(in, arch);
            }
        }
        Path src = dir.resolve(name + ".dsp");
        Files.write(src, dsp.getBytes(StandardCharsets.UTF_8));
        Path cpp = dir.resolve(name + ".cpp");
        Path exe = dir.resolve(name);
        List<String> faust = new ArrayList<>(List.of("faust"));
        if (doublePrecision) {
            faust.add("-double");
        }
        faust.addAll(List.of("-a", arch.toString(), src.toString(), "-o", cpp.toString()));
        faust.addAll(1, List.of("-t", Integer.toString(timeoutSeconds)));   // faust's own timeout is 120 s
        if (faustMemoryKb > 0) {
            faust = List.of("bash", "-c", "ulimit -v " + faustMemoryKb + " && exec \"$0\" \"$@\"", "faust");
            faust = new ArrayList<>(faust);
            faust.addAll(List.of("-t", Integer.toString(timeoutSeconds)));
            if (doublePrecision) {
                faust.add("-double");
            }
            faust.addAll(List.of("-a", arch.toString(), src.toString(), "-o", cpp.toString()));
        }
        long t0 = System.nanoTime();
        run(faust, dir, timeoutSeconds, null);
        long t1 = System.nanoTime();
        run(List.of("g++", gccOptimisation, "-std=c++11", cpp.toString(), "-o", exe.toString()), dir, timeoutSeconds,
                null);
        long t2 = System.nanoTime();
        return new Program(exe, (t1 - t0) / 1_000_000, (t2 - t1) / 1_000_000);
    }

    /**
     * Renders samples.
     *
     * @param args extra arguments for the architecture ({@code -in c n v}, {@code -set label value})
     * @return the outputs, [output][sample]
     */
    public static double[][] render(Program p, int samples, List<String> args, int timeoutSeconds)
            throws IOException {
        List<String> cmd = new ArrayList<>(List.of(p.executable.toString(), Integer.toString(samples)));
        cmd.addAll(args);
        Path out = p.executable.resolveSibling(p.executable.getFileName() + ".out");
        run(cmd, p.executable.getParent(), timeoutSeconds, out);
        List<String> lines = Files.readAllLines(out, StandardCharsets.UTF_8);
        if (lines.size() != samples) {
            throw new IllegalStateException(p.executable + " printed " + lines.size() + " lines for " + samples
                    + " samples");
        }
        int channels = lines.get(0).trim().split(" ").length;
        double[][] r = new double[channels][samples];
        for (int s = 0; s < samples; s++) {
            String[] v = lines.get(s).trim().split(" ");
            for (int c = 0; c < channels; c++) {
                r[c][s] = Double.parseDouble(v[c]);
            }
        }
        return r;
    }

    /** Runs the program's benchmark mode; @return nanoseconds per sample. */
    public static double nanosPerSample(Program p, int samples, int timeoutSeconds) throws IOException {
        Path out = p.executable.resolveSibling(p.executable.getFileName() + ".bench");
        run(List.of(p.executable.toString(), Integer.toString(samples), "-bench"), p.executable.getParent(),
                timeoutSeconds, out);
        String line = new String(Files.readAllBytes(out), StandardCharsets.UTF_8).trim();
        return Double.parseDouble(line.substring(0, line.indexOf(' ')));
    }

    /**
     * Runs a command, bounded in time; standard output goes to {@code stdout} (or is discarded).
     *
     * @throws IllegalStateException on a timeout (the process is killed) or a non-zero exit, with its error output
     */
    static void run(List<String> cmd, Path dir, int timeoutSeconds, Path stdout) throws IOException {
        ProcessBuilder pb = new ProcessBuilder(cmd);
        if (dir != null) {
            pb.directory(dir.toFile());
        }
        Path err = Files.createTempFile("tactus-faust", ".err");
        pb.redirectError(err.toFile());
        pb.redirectOutput(stdout == null ? ProcessBuilder.Redirect.DISCARD : ProcessBuilder.Redirect.to(stdout.toFile()));
        Process proc = pb.start();
        try {
            if (!proc.waitFor(timeoutSeconds, TimeUnit.SECONDS)) {
                proc.destroyForcibly();
                throw new IllegalStateException(String.join(" ", cmd.subList(0, Math.min(2, cmd.size())))
                        + " did not finish within " + timeoutSeconds + " s");
            }
            if (proc.exitValue() != 0) {
                String msg = new String(Files.readAllBytes(err), StandardCharsets.UTF_8);
                throw new IllegalStateException(cmd.get(0) + " failed (status " + proc.exitValue() + "): "
                        + (msg.length() > 2000 ? msg.substring(0, 2000) + "..." : msg));
            }
        } catch (InterruptedException e) {
            proc.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IllegalStateException(cmd.get(0) + " interrupted", e);
        } finally {
            Files.deleteIfExists(err);
        }
    }
}
