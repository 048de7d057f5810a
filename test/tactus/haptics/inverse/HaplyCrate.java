package tactus.haptics.inverse;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Haply's {@code haply} crate for the fidelity tests: the pinned version (test-resources/haply-probe/Cargo.lock),
 * its sources in the Cargo registry (fetched with cargo if they are not there yet; never copied into this
 * repository), and the probe program built with it.
 */
final class HaplyCrate {
    private HaplyCrate() {
    }

    /** The probe's Cargo project. */
    static Path probeDir() {
        String p = System.getProperty("tactus.haply.probe");
        return Paths.get(p != null ? p : "test-resources/haply-probe").toAbsolutePath();
    }

    /** Where the probe is built (Cargo's target directory). */
    static Path targetDir() {
        String p = System.getProperty("tactus.haply.probe.target");
        return Paths.get(p != null ? p : "build/haply-probe").toAbsolutePath();
    }

    /** The cargo program: on the PATH, or in ~/.cargo/bin (rustup's place). */
    static String cargo() {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            File f = new File(dir, "cargo");
            if (f.canExecute()) {
                return f.getAbsolutePath();
            }
        }
        File home = new File(cargoHome().toFile(), "bin/cargo");
        if (home.canExecute()) {
            return home.getAbsolutePath();
        }
        throw new AssertionError("cargo is not installed (not on the PATH nor in ~/.cargo/bin): the fidelity tests build a "
                + "program with Haply's crate; .ci/run installs it with rustup");
    }

    static Path cargoHome() {
        String h = System.getenv("CARGO_HOME");
        return h != null ? Paths.get(h) : Paths.get(System.getProperty("user.home"), ".cargo");
    }

    /** The pinned version of the haply crate, from the probe's Cargo.lock. */
    static String version() throws IOException {
        String lock = new String(Files.readAllBytes(probeDir().resolve("Cargo.lock")), StandardCharsets.UTF_8);
        Matcher m = Pattern.compile("name = \"haply\"\\s*\\nversion = \"([^\"]+)\"").matcher(lock);
        if (!m.find()) {
            throw new AssertionError("Cargo.lock of the probe does not pin the haply crate");
        }
        return m.group(1);
    }

    /** The crate's source folder in the Cargo registry, fetching it first if needed. */
    static Path sources() throws IOException, InterruptedException {
        String dirName = "haply-" + version();
        Path found = findSources(dirName);
        if (found == null) {
            run(probeDir(), 600, cargo(), "fetch", "--locked");
            found = findSources(dirName);
        }
        if (found == null) {
            throw new AssertionError(dirName + " is not in " + cargoHome().resolve("registry/src") + " even after cargo fetch");
        }
        return found;
    }

    private static Path findSources(String dirName) throws IOException {
        Path src = cargoHome().resolve("registry/src");
        if (!Files.isDirectory(src)) {
            return null;
        }
        try (Stream<Path> s = Files.list(src)) {
            return s.map(p -> p.resolve(dirName)).filter(Files::isDirectory).findFirst().orElse(null);
        }
    }

    /** Builds the probe (offline once the crates are fetched) and returns its executable. */
    static Path buildProbe() throws IOException, InterruptedException {
        String cargo = cargo();
        String out = run(probeDir(), 1200, cargo, "build", "--locked", "--offline", "--target-dir", targetDir().toString());
        if (out == null) {   // not fetched yet: fetch, then build
            run(probeDir(), 600, cargo, "fetch", "--locked");
            out = run(probeDir(), 1200, cargo, "build", "--locked", "--offline", "--target-dir", targetDir().toString());
        }
        if (out == null) {
            throw new AssertionError("cargo could not build the haply probe (see the output above)");
        }
        return targetDir().resolve("debug/haply-probe");
    }

    /** Runs a command in dir, bounded; returns its output, or null if it failed. */
    static String run(Path dir, long seconds, String... command) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true);
        Process p = pb.start();
        byte[][] holder = new byte[1][];
        Thread reader = new Thread(() -> {
            try {
                holder[0] = p.getInputStream().readAllBytes();
            } catch (IOException e) {
                holder[0] = new byte[0];
            }
        });
        reader.start();
        if (!p.waitFor(seconds, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError(String.join(" ", command) + " did not finish within " + seconds + " s");
        }
        reader.join(10_000);
        String text = holder[0] == null ? "" : new String(holder[0], StandardCharsets.UTF_8);
        if (p.exitValue() != 0) {
            System.out.println(String.join(" ", command) + " failed (" + p.exitValue() + "):\n" + text);
            return null;
        }
        return text;
    }

    /**
     * Every {@code json!({...})} literal of the crate's Rust sources and tests (they are plain JSON), with the file
     * and offset it came from.
     */
    static List<String[]> jsonLiterals(Path crate) throws IOException {
        List<String[]> found = new ArrayList<>();
        List<Path> files;
        try (Stream<Path> s = Files.walk(crate)) {
            files = s.filter(p -> p.toString().endsWith(".rs") && !p.toString().contains("/target/")).sorted()
                    .collect(java.util.stream.Collectors.toList());
        }
        for (Path f : files) {
            String text = new String(Files.readAllBytes(f), StandardCharsets.UTF_8);
            int i = 0;
            while ((i = text.indexOf("json!(", i)) >= 0) {
                int start = i + "json!(".length();
                while (start < text.length() && Character.isWhitespace(text.charAt(start))) {
                    start++;
                }
                int end = balancedEnd(text, start);
                if (end > start) {
                    found.add(new String[] {crate.relativize(f) + ":" + i, text.substring(start, end)});
                }
                i = Math.max(end, start);
            }
        }
        return found;
    }

    /** The end (exclusive) of the JSON object or array starting at start, or -1. */
    private static int balancedEnd(String s, int start) {
        char open = s.charAt(start);
        if (open != '{' && open != '[') {
            return -1;
        }
        int depth = 0;
        for (int i = start; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '"') {
                for (i++; i < s.length() && s.charAt(i) != '"'; i++) {
                    if (s.charAt(i) == '\\') {
                        i++;
                    }
                }
            } else if (c == '{' || c == '[') {
                depth++;
            } else if (c == '}' || c == ']') {
                depth--;
                if (depth == 0) {
                    return i + 1;
                }
            }
        }
        return -1;
    }
}
