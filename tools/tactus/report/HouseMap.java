package tactus.report;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The figures of the house (issue 26), counted from the sources so that anyone can count them again:
 *
 * <pre>
 *   java tools/tactus/report/HouseMap.java src            # or any source root
 *   java tools/tactus/report/HouseMap.java src --arrows   # also list the arrows that run back up
 * </pre>
 *
 * <p>How it counts. Each top-level type of the source root is a node. A file uses another type when, with its
 * comments, string literals and enum constant names removed, it imports it (single-type or static import), names it with its package
 * ({@code tactus.engine.Engine}), or names it by its simple name when both are in the same package or the file
 * imports that package with {@code *}. Rooms are packages: a room uses another room when one of its files uses one
 * of that room's types. An arrow "runs back up" when it points against the house's order: the order is found by
 * the strongly connected components in topological order and, inside each, the greedy heuristic of Eades, Lin and Smyth (take sinks to the bottom, sources to the top, otherwise the node
 * with the most outgoing minus incoming arrows to the top; ties by name), and the arrows it cannot point downward
 * are the ones counted; an acyclic graph has none. The same count is given for the rooms (packages) and for the
 * types (files), and it also prints the files of the top package and the code lines of {@code PhysicalModel}
 * (lines that are neither blank nor comment).
 */
public final class HouseMap {
    private static final Pattern PACKAGE = Pattern.compile("(?m)^package\\s+([\\w.]+)\\s*;");
    private static final Pattern IMPORT = Pattern.compile("(?m)^import\\s+(static\\s+)?([\\w.]+?)(\\.\\*)?\\s*;");
    /** The constants of an enum: their names are not uses of the types they may spell (matModuleType.Mass3D). */
    private static final Pattern ENUM_CONSTANTS = Pattern.compile("\\benum\\s+\\w+[^{]*\\{([^;}]*)");
    private static final Pattern WORD = Pattern.compile("[A-Za-z_$][\\w$]*(?:\\s*\\.\\s*[A-Za-z_$][\\w$]*)*");

    private HouseMap() {
    }

    public static void main(String[] args) throws IOException {
        Path root = Paths.get(args.length > 0 ? args[0] : "src");
        boolean list = args.length > 1 && args[1].equals("--arrows");
        Map<String, String> code = new TreeMap<>(); // qualified type name -> code without comments and strings
        Map<String, String> pkgOf = new HashMap<>();
        try (Stream<Path> all = Files.walk(root)) {
            for (Path p : (Iterable<Path>) all.filter(f -> f.toString().endsWith(".java"))::iterator) {
                String name = p.getFileName().toString().replace(".java", "");
                if (name.equals("package-info")) {
                    continue;
                }
                String text = stripComments(new String(Files.readAllBytes(p), StandardCharsets.UTF_8));
                Matcher pm = PACKAGE.matcher(text);
                String pkg = pm.find() ? pm.group(1) : "";
                code.put(pkg + "." + name, text);
                pkgOf.put(pkg + "." + name, pkg);
            }
        }
        Map<String, Set<String>> typeArrows = new TreeMap<>();
        for (Map.Entry<String, String> e : code.entrySet()) {
            typeArrows.put(e.getKey(), uses(e.getKey(), e.getValue(), pkgOf));
        }
        Map<String, Set<String>> roomArrows = new TreeMap<>();
        for (Map.Entry<String, Set<String>> e : typeArrows.entrySet()) {
            String from = pkgOf.get(e.getKey());
            roomArrows.computeIfAbsent(from, k -> new TreeSet<>());
            for (String t : e.getValue()) {
                if (!pkgOf.get(t).equals(from)) {
                    roomArrows.get(from).add(pkgOf.get(t));
                }
            }
        }
        report("rooms (packages)", roomArrows, list);
        report("types (files)", typeArrows, list);
        try (Stream<Path> files = Files.list(root.resolve("tactus"))) {
            System.out.println("files in the top package tactus (src/tactus/*.java): "
                    + files.filter(f -> f.toString().endsWith(".java")).count());
        }
        Path pm = root.resolve("tactus/PhysicalModel.java");
        if (Files.exists(pm)) {
            System.out.println("PhysicalModel.java code lines (neither blank nor comment): " + codeLines(pm));
        }
    }

    /** @return the types of the source root that one file uses, itself left out. */
    private static Set<String> uses(String self, String text, Map<String, String> pkgOf) {
        String pkg = pkgOf.get(self);
        Set<String> star = new HashSet<>();
        Set<String> found = new TreeSet<>();
        Matcher im = IMPORT.matcher(text);
        while (im.find()) {
            String name = im.group(2);
            if (im.group(3) != null && im.group(1) == null) {
                star.add(name);
            } else {
                String type = typeOf(name, pkgOf);
                if (type != null) {
                    found.add(type);
                }
            }
        }
        String body = IMPORT.matcher(PACKAGE.matcher(text).replaceAll("")).replaceAll("");
        Matcher en = ENUM_CONSTANTS.matcher(body);
        if (en.find()) {
            body = body.substring(0, en.start(1)) + body.substring(en.end(1));
        }
        Map<String, List<String>> bySimpleName = new HashMap<>();
        for (String t : pkgOf.keySet()) {
            String p = pkgOf.get(t);
            if (p.equals(pkg) || star.contains(p)) {
                bySimpleName.computeIfAbsent(t.substring(p.length() + 1), k -> new ArrayList<>()).add(t);
            }
        }
        Matcher w = WORD.matcher(body);
        while (w.find()) {
            String dotted = w.group().replaceAll("\\s+", "");
            String type = typeOf(dotted, pkgOf);
            if (type != null && dotted.contains(".") && !dotted.startsWith(type.substring(type.lastIndexOf('.') + 1))) {
                found.add(type); // a qualified name: tactus.engine.Engine.x
                continue;
            }
            List<String> local = bySimpleName.get(dotted.split("\\.")[0]);
            if (local != null) {
                String same = pkg + "." + dotted.split("\\.")[0];
                found.add(local.contains(same) ? same : local.get(0));
            }
        }
        found.remove(self);
        return found;
    }

    /** @return the longest prefix of a dotted name that is a type of the source root, or null. */
    private static String typeOf(String dotted, Map<String, String> pkgOf) {
        String s = dotted;
        while (true) {
            if (pkgOf.containsKey(s)) {
                return s;
            }
            int dot = s.lastIndexOf('.');
            if (dot < 0) {
                return null;
            }
            s = s.substring(0, dot);
        }
    }

    private static void report(String what, Map<String, Set<String>> arrows, boolean list) {
        int total = 0;
        for (Set<String> s : arrows.values()) {
            total += s.size();
        }
        List<String> order = order(arrows);
        Map<String, Integer> rank = new HashMap<>();
        for (int i = 0; i < order.size(); i++) {
            rank.put(order.get(i), i);
        }
        List<String> back = new ArrayList<>();
        for (Map.Entry<String, Set<String>> e : arrows.entrySet()) {
            for (String t : e.getValue()) {
                if (rank.get(t) < rank.get(e.getKey())) {
                    back.add(e.getKey() + " -> " + t);
                }
            }
        }
        System.out.println(what + ": " + arrows.size() + " nodes, " + total + " arrows, " + back.size()
                + " of them running back up");
        if (list) {
            for (String b : back) {
                System.out.println("  back up: " + b);
            }
        }
    }

    /**
     * The house's order, users first (top), what they use after them (below): the strongly connected components in
     * topological order, and inside each component the order of Eades, Lin and Smyth.
     */
    private static List<String> order(Map<String, Set<String>> arrows) {
        Map<String, Set<String>> all = new TreeMap<>();
        for (Map.Entry<String, Set<String>> e : arrows.entrySet()) {
            all.computeIfAbsent(e.getKey(), k -> new TreeSet<>()).addAll(e.getValue());
            for (String t : e.getValue()) {
                all.computeIfAbsent(t, k -> new TreeSet<>());
            }
        }
        List<List<String>> components = new Tarjan(all).components; // sinks first
        List<String> order = new ArrayList<>();
        for (int i = components.size() - 1; i >= 0; i--) {
            Set<String> members = new TreeSet<>(components.get(i));
            Map<String, Set<String>> inside = new TreeMap<>();
            for (String n : members) {
                Set<String> s = new TreeSet<>(all.get(n));
                s.retainAll(members);
                inside.put(n, s);
            }
            order.addAll(greedy(inside));
        }
        return order;
    }

    /** Tarjan's strongly connected components, each emitted after every component it uses (sinks first). */
    private static final class Tarjan {
        final List<List<String>> components = new ArrayList<>();
        private final Map<String, Set<String>> arrows;
        private final Map<String, Integer> index = new HashMap<>();
        private final Map<String, Integer> low = new HashMap<>();
        private final List<String> stack = new ArrayList<>();
        private final Set<String> onStack = new HashSet<>();

        Tarjan(Map<String, Set<String>> arrows) {
            this.arrows = arrows;
            for (String n : arrows.keySet()) {
                if (!index.containsKey(n)) {
                    visit(n);
                }
            }
        }

        private void visit(String n) {
            index.put(n, index.size());
            low.put(n, index.get(n));
            stack.add(n);
            onStack.add(n);
            for (String t : arrows.get(n)) {
                if (!index.containsKey(t)) {
                    visit(t);
                    low.put(n, Math.min(low.get(n), low.get(t)));
                } else if (onStack.contains(t)) {
                    low.put(n, Math.min(low.get(n), index.get(t)));
                }
            }
            if (low.get(n).equals(index.get(n))) {
                List<String> c = new ArrayList<>();
                String m;
                do {
                    m = stack.remove(stack.size() - 1);
                    onStack.remove(m);
                    c.add(m);
                } while (!m.equals(n));
                components.add(c);
            }
        }
    }

    /** The order of Eades, Lin and Smyth inside one component: users first (top), what they use after them. */
    private static List<String> greedy(Map<String, Set<String>> arrows) {
        Map<String, Set<String>> out = new TreeMap<>();
        Map<String, Set<String>> in = new TreeMap<>();
        for (String n : arrows.keySet()) {
            out.put(n, new TreeSet<>(arrows.get(n)));
            in.computeIfAbsent(n, k -> new TreeSet<>());
            for (String t : arrows.get(n)) {
                in.computeIfAbsent(t, k -> new TreeSet<>()).add(n);
                out.computeIfAbsent(t, k -> new TreeSet<>());
            }
        }
        List<String> top = new ArrayList<>();
        List<String> bottom = new ArrayList<>();
        Set<String> left = new TreeSet<>(out.keySet());
        while (!left.isEmpty()) {
            boolean moved = true;
            while (moved) {
                moved = false;
                for (String n : new ArrayList<>(left)) {
                    if (out.get(n).isEmpty()) {
                        bottom.add(0, n);
                        remove(n, left, out, in);
                        moved = true;
                    }
                }
                for (String n : new ArrayList<>(left)) {
                    if (in.get(n).isEmpty()) {
                        top.add(n);
                        remove(n, left, out, in);
                        moved = true;
                    }
                }
            }
            if (left.isEmpty()) {
                break;
            }
            String best = null;
            int bestDelta = Integer.MIN_VALUE;
            for (String n : left) {
                int delta = out.get(n).size() - in.get(n).size();
                if (delta > bestDelta) {
                    best = n;
                    bestDelta = delta;
                }
            }
            top.add(best);
            remove(best, left, out, in);
        }
        top.addAll(bottom);
        return top;
    }

    private static void remove(String n, Set<String> left, Map<String, Set<String>> out, Map<String, Set<String>> in) {
        left.remove(n);
        for (String t : out.get(n)) {
            in.get(t).remove(n);
        }
        for (String s : in.get(n)) {
            out.get(s).remove(n);
        }
        out.get(n).clear();
        in.get(n).clear();
    }

    /** @return the text with comments removed and string and character literals emptied; line breaks are kept. */
    static String stripComments(String s) {
        StringBuilder b = new StringBuilder(s.length());
        int i = 0;
        int n = s.length();
        while (i < n) {
            char c = s.charAt(i);
            if (c == '/' && i + 1 < n && s.charAt(i + 1) == '/') {
                while (i < n && s.charAt(i) != '\n') {
                    i++;
                }
            } else if (c == '/' && i + 1 < n && s.charAt(i + 1) == '*') {
                i += 2;
                while (i + 1 < n && !(s.charAt(i) == '*' && s.charAt(i + 1) == '/')) {
                    if (s.charAt(i) == '\n') {
                        b.append('\n');
                    }
                    i++;
                }
                i += 2;
            } else if (c == '"' || c == '\'') {
                if (c == '"' && s.startsWith("\"\"\"", i)) {
                    int end = s.indexOf("\"\"\"", i + 3);
                    i = end < 0 ? n : end + 3;
                    b.append("\"\"");
                    continue;
                }
                b.append(c);
                i++;
                while (i < n && s.charAt(i) != c) {
                    i += s.charAt(i) == '\\' ? 2 : 1;
                }
                b.append(c);
                i++;
            } else {
                b.append(c);
                i++;
            }
        }
        return b.toString();
    }

    /** @return the lines of a file that hold code: neither blank nor inside or made of a comment. */
    static int codeLines(Path p) throws IOException {
        String text = stripComments(new String(Files.readAllBytes(p), StandardCharsets.UTF_8));
        int lines = 0;
        for (String line : text.split("\n", -1)) {
            if (!line.trim().isEmpty()) {
                lines++;
            }
        }
        return lines;
    }
}
