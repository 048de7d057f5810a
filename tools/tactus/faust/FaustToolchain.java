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
        long t0 = System.nanoTime();
        Path cpp = faustCpp(dsp, dir, name, doublePrecision, timeoutSeconds, false);
        long t1 = System.nanoTime();
        Path exe = gpp(cpp, dir.resolve(name), gccOptimisation, timeoutSeconds, false);
        long t2 = System.nanoTime();
        return new Program(exe, (t1 - t0) / 1_000_000, (t2 - t1) / 1_000_000);
    }

    /**
     * Translates a program to C++ with {@code faust} against the offline architecture.
     *
     * @param reuse true to skip faust when {@code dir} already holds the C++ of this very source (same text)
     * @return the C++ file, {@code dir/name.cpp}
     */
    public static Path faustCpp(String dsp, Path dir, String name, boolean doublePrecision, int timeoutSeconds,
                                boolean reuse) throws IOException {
        dir = dir.toAbsolutePath();
        Files.createDirectories(dir);
        Path arch = dir.resolve("tactus-offline.cpp");
        byte[] archText;
        try (InputStream in = FaustToolchain.class.getResourceAsStream("offline.cpp")) {
            if (in == null) {
                throw new IOException("offline.cpp is not on the class path next to FaustToolchain");
            }
            archText = in.readAllBytes();
        }
        Path src = dir.resolve(name + ".dsp");
        Path cpp = dir.resolve(name + ".cpp");
        byte[] dspText = dsp.getBytes(StandardCharsets.UTF_8);
        boolean sameArch = Files.exists(arch) && java.util.Arrays.equals(Files.readAllBytes(arch), archText);
        if (reuse && sameArch && Files.exists(cpp) && Files.exists(src)
                && java.util.Arrays.equals(Files.readAllBytes(src), dspText)
                && Files.getLastModifiedTime(cpp).compareTo(Files.getLastModifiedTime(src)) >= 0) {
            return cpp;
        }
        if (!sameArch) {
            Files.write(arch, archText);
        }
        Files.write(src, dspText);
        Files.deleteIfExists(cpp);
        List<String> faust = new ArrayList<>();
        if (faustMemoryKb > 0) {
            faust.addAll(List.of("bash", "-c", "ulimit -v " + faustMemoryKb + " && exec \"$0\" \"$@\""));
        }
        faust.addAll(List.of("faust", "-t", Integer.toString(timeoutSeconds)));   // faust's own timeout is 120 s
        if (doublePrecision) {
            faust.add("-double");
        }
        faust.addAll(List.of("-a", arch.toString(), src.toString(), "-o", cpp.toString()));
        run(faust, dir, timeoutSeconds, null);
        return cpp;
    }

    /**
     * Compiles C++ with {@code g++}.
     *
     * @param options g++ options separated by spaces, for example "-O3" or "-O3 -march=native"
     * @param reuse true to skip g++ when the executable is newer than the C++
     * @return the executable
     */
    public static Path gpp(Path cpp, Path exe, String options, int timeoutSeconds, boolean reuse) throws IOException {
        cpp = cpp.toAbsolutePath();
        exe = exe.toAbsolutePath();
        if (reuse && Files.exists(exe) && Files.getLastModifiedTime(exe).compareTo(Files.getLastModifiedTime(cpp)) > 0) {
            return exe;
        }
        List<String> gcc = new ArrayList<>(List.of("g++"));
        gcc.addAll(java.util.Arrays.asList(options.trim().split("\\s+")));
        gcc.addAll(List.of("-std=c++11", cpp.toString(), "-o", exe.toString()));
        Files.deleteIfExists(exe);
        run(gcc, cpp.getParent(), timeoutSeconds, null);
        return exe;
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
        return benchmark(p.executable, samples, 1, timeoutSeconds)[0];
    }

    /**
     * Runs the program's benchmark mode ({@code -bench}, after its own warm-up of a tenth of the samples).
     *
     * @param voices instances rendered side by side ({@code -voices})
     * @return nanoseconds per sample of wall-clock time and of the process's CPU time
     */
    public static double[] benchmark(Path exe, int samples, int voices, int timeoutSeconds) throws IOException {
        Path out = exe.resolveSibling(exe.getFileName() + ".bench");
        run(List.of(exe.toString(), Integer.toString(samples), "-bench", "-voices", Integer.toString(voices)),
                exe.getParent(), timeoutSeconds, out);
        String line = new String(Files.readAllBytes(out), StandardCharsets.UTF_8).trim();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("^([0-9.]+) ns/sample \\(cpu ([0-9.]+) ns").matcher(line);
        if (!m.find()) {
            throw new IllegalStateException(exe + " -bench printed " + line);
        }
        return new double[] {Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2))};
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
