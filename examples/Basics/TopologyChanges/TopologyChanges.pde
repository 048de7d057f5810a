/*
 * TopologyChanges: a net made by TopoGenerator hangs from its top row and tears
 * down the middle on its own, one link at a time; keys cut links, remove
 * masses, pin them and hang new weights while it runs. The generic renderer
 * (ModelRenderer) draws it in plain 2D (JAVA2D), links turning red as they
 * stretch.
 *
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y points up.
 */

import tactus.*;

PhysicalModel mdl;
ModelRenderer renderer;
int simRate = 1000;
int dispRate = 60;
int nx = 14, ny = 8;   // masses across and down
float spacing = 50;    // grid spacing
int tears = 0;         // links cut by the automatic tear
int weights = 0;       // weights added with the A key

void setup() {
  size(900, 560);
  frameRate(dispRate);
  buildNet();

  renderer = new ModelRenderer(this);
  renderer.setColor(matModuleType.Mass2DPlane, 230, 150, 40);
  renderer.setSize(matModuleType.Mass2DPlane, 5);
  renderer.setColor(matModuleType.Ground3D, 60, 60, 60);
  renderer.setSize(matModuleType.Ground3D, 6);
  renderer.setColor(matModuleType.Mass3D, 120, 60, 160);
  renderer.setSize(matModuleType.Mass3D, 4);
  renderer.setScaling(matModuleType.Mass3D, 2);   // heavier weights are drawn bigger
  renderer.setColor(linkModuleType.SpringDamper3D, 40, 120, 200, 255);
  renderer.setSize(linkModuleType.SpringDamper3D, 1);
  renderer.setStrainColor(linkModuleType.SpringDamper3D, 230, 30, 30, 255);
  renderer.setStrainGradient(linkModuleType.SpringDamper3D, true, 0.3);
  renderer.setZoomVector(1, 1, 1);
  renderer.setScale(1);
  renderer.displayMats(true);
}

// A 14 x 8 net of Mass2DPlane (they stay in the x-y plane), hung by its top row.
void buildNet() {
  mdl = new PhysicalModel(simRate, dispRate);
  mdl.setGravityDirection(new PVector(0, 1, 0));
  mdl.setGravity(0.0003);
  mdl.setFriction(0.0005);
  TopoGenerator net = new TopoGenerator(mdl, "net", "link");
  net.setDim(nx, ny, 1, 1);                   // span 1: edges and diagonals of each cell
  net.set2DPlane(true);
  net.setParams(1, 0.01, 0.001);              // mass, stiffness, damping
  net.setGeometry(spacing, spacing * 0.9);    // rest lengths shorter than the grid: the net is taut
  net.setTranslation(125, 100, 0);
  net.setMatSubsetName("knots");
  net.setLinkSubsetName("threads");
  net.addBoundaryCondition(Bound.Y_RIGHT);    // the row of highest j (the top) is fixed
  net.generate();
  mdl.init();
  tears = 0;
  weights = 0;
}

void draw() {
  // The automatic tear: every 10 frames, cut the lowest link that crosses the middle of the net.
  if (frameCount % 10 == 0) {
    tearOneLink();
  }
  // After two seconds, a knot at the bottom falls out, with its links.
  if (frameCount == 120 && mdl.matExists("net_2_0_0")) {
    mdl.removeMatAndConnectedLinks("net_2_0_0");
  }
  mdl.draw_physics();

  background(250);
  pushMatrix();
  translate(0, height);
  scale(1, -1);             // the model's y points up
  renderer.renderModel(mdl);
  popMatrix();

  fill(20);
  textSize(13);
  textAlign(LEFT, TOP);
  text(mdl.getNumberOfMats() + " masses, " + mdl.getNumberOfLinks() + " links; torn links: " + tears
    + ", weights added: " + weights + ", threads still in their subset: " + mdl.getSubsetMembers("threads").length
    + ", drawn at scale " + nf(renderer.getScale(), 0, 1), 12, 10);
  text("C: cut the links starting at the knot nearest the mouse   X: remove that knot   P: pin it   "
    + "A: hang a weight from it   N: a new net", 12, height - 22);
}

// Cut the lowest link whose ends lie on both sides of the middle of the net.
void tearOneLink() {
  float middle = 125 + spacing * (nx - 1) / 2;
  int lowest = -1;
  float lowestY = Float.MAX_VALUE;
  for (int i = 0; i < mdl.getNumberOfLinks(); i++) {
    Vect3D a = mdl.getLinkPos1At(i);
    Vect3D b = mdl.getLinkPos2At(i);
    if ((a.x - middle) * (b.x - middle) < 0 && Math.min(a.y, b.y) < lowestY) {
      lowestY = (float) Math.min(a.y, b.y);
      lowest = i;
    }
  }
  if (lowest >= 0) {
    mdl.removeLink(lowest);
    tears++;
  }
}

// The index of the free knot nearest the mouse.
int nearestKnot() {
  float mx = mouseX;
  float my = height - mouseY;
  int best = -1;
  double bestD = Double.MAX_VALUE;
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    if (mdl.getMatTypeAt(i) != matModuleType.Mass2DPlane) {
      continue;
    }
    Vect3D p = mdl.getMatPosAt(i);
    double d = dist(mx, my, (float) p.x, (float) p.y);
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  }
  return best;
}

void keyPressed() {
  int knot = nearestKnot();
  String name = knot < 0 ? "" : mdl.getMatNameAt(knot);
  if (key == 'c' || key == 'C') {
    // The generator names every link that starts at knot (i, j, k) "net1_" + i + j + k, so one name
    // reaches all of them, one after the other.
    if (knot >= 0) {
      String[] ijk = name.split("_");
      String linkName = "net1_" + ijk[1] + ijk[2] + ijk[3];
      while (mdl.linkExists(linkName)) {
        mdl.removeLink(linkName);
      }
    }
  } else if ((key == 'x' || key == 'X') && knot >= 0) {
    mdl.removeMatAndConnectedLinks(knot);
  } else if ((key == 'p' || key == 'P') && knot >= 0) {
    mdl.changeToFixedPoint(name);
  } else if ((key == 'a' || key == 'A') && knot >= 0) {
    // New modules join a running model: a weight 60 units below the knot, on a spring.
    weights++;
    Vect3D p = mdl.getMatPosAt(knot);
    String w = "weight" + weights;
    mdl.addMass3D(w, 3, new Vect3D(p.x, p.y - 60, 0), new Vect3D(0, 0, 0));
    mdl.addSpringDamper3D("hanger" + weights, 60, 0.02, 0.002, name, w);
  } else if (key == 'n' || key == 'N') {
    buildNet();
  }
}
