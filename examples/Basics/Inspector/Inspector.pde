/*
 * Inspector: a hammer on a springy handle swings over three oscillator bars and
 * strikes them, while the panels show every number of the selected mass, the
 * selected link and the model. Keys change one module at a time, by index or by
 * name, or whole subsets, change the simulation rate, and pause and step the
 * model.
 *
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y points up.
 */

import tactus.*;

PhysicalModel mdl;
MidiController barKnob;
int simRate = 1000;
int dispRate = 60;
int selMat = 0;
int selLink = 0;
boolean paused = false;
boolean autoSelect = true;   // the selection walks through the model until a key is pressed
Vect3D[] start;              // where each mass started, for key R

void setup() {
  size(960, 600);
  frameRate(dispRate);
  println("Inspector, on Tactus " + PhysicalModel.version());
  build();
}

void build() {
  if (mdl == null) {
    mdl = new PhysicalModel(simRate, dispRate);
  } else {
    mdl.clearModel();        // the same model object, emptied: names, subsets and controllers too
  }
  mdl.setGravityDirection(new PVector(0, 1, 0));
  mdl.setGravity(0.0003);
  mdl.setFriction(0.0002);
  mdl.addGround3D("pivot", new Vect3D(505, 520, 0));
  mdl.addMass3D("hammer", 2, new Vect3D(705, 520, 0), new Vect3D(0, 0, 0));
  mdl.addSpringDamper3D("handle", 200, 0.05, 0.002, "pivot", "hammer");
  mdl.createMatSubset("bars");
  mdl.createLinkSubset("strikes");
  for (int i = 0; i < 3; i++) {
    String bar = "bar" + i;
    mdl.addOsc3D(bar, 1, 0.004 * (i + 1), 0.0002, new Vect3D(445 + 60 * i, 305, 0), new Vect3D(0, 0, 0));
    mdl.addMatToSubset(bar, "bars");
    mdl.addContact3D("strike" + i, 25, 0.05, 0.001, "hammer", bar);
    mdl.addLinkToSubset("strike" + i, "strikes");
  }
  mdl.init();
  start = new Vect3D[mdl.getNumberOfMats()];
  for (int i = 0; i < start.length; i++) {
    start[i] = new Vect3D();
    start[i].set(mdl.getMatPosAt(i));
  }
  // A knob for the bars' stiffness (controller 2), made with the constructor, and one with the older
  // spelling that the paper's sketches use, for the strikes' damping (controller 3).
  barKnob = new MidiController(mdl, 2, 0.001, 0.02, "bars", "stiffness", 0.2);
  MidiControler.addMidiControler(mdl, 3, 0.0005, 0.01, "strikes", "damping");
  selMat = 0;
  selLink = 0;
}

void draw() {
  if (!paused) {
    mdl.draw_physics();
  }
  if (autoSelect && frameCount % 40 == 0) {
    selMat = (selMat + 1) % mdl.getNumberOfMats();
    selLink = (selLink + 1) % mdl.getNumberOfLinks();
  }
  background(250);
  drawModel();
  drawPanels();
}

void drawModel() {
  for (int i = 0; i < mdl.getNumberOfLinks(); i++) {
    Vect3D a = mdl.getLinkPos1At(i);
    Vect3D b = mdl.getLinkPos2At(i);
    boolean touching = mdl.getLinkTypeAt(i) == linkModuleType.Contact3D && mdl.getLinkDistanceAt(i) < mdl.getLinkDRestAt(i);
    if (mdl.getLinkTypeAt(i) == linkModuleType.Contact3D && !touching && i != selLink) {
      continue;
    }
    stroke(i == selLink ? color(230, 60, 20) : color(90));
    strokeWeight(i == selLink ? 3 : 1.5);
    line((float) a.x, height - (float) a.y, (float) b.x, height - (float) b.y);
  }
  strokeWeight(1);
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    PVector p = mdl.getMatPosAt(i).toPVector();
    noStroke();
    switch (mdl.getMatTypeAt(i)) {
    case Ground3D:
      fill(60);
      rect(p.x - 5, height - p.y - 5, 10, 10);
      break;
    case Osc3D:
      fill(130, 80, 200);
      rect(p.x - 22, height - p.y - 5, 44, 10);
      break;
    case UNDEFINED:
      break;
    default:
      fill(200, 110, 30);
      ellipse(p.x, height - p.y, 24, 24);
      break;
    }
    if (i == selMat) {
      noFill();
      stroke(230, 60, 20);
      ellipse(p.x, height - p.y, 36, 36);
      // its velocity, a tenth of a second ahead
      Vect3D v = mdl.getMatVelAt(i).mult(0.1);
      line(p.x, height - p.y, p.x + (float) v.x, height - p.y - (float) v.y);
    }
  }
}

void drawPanels() {
  fill(20);
  textSize(12);
  textAlign(LEFT, TOP);
  String name = mdl.getMatNameAt(selMat);
  Vect3D pos;
  Vect3D vel;
  Vect3D frc;
  // Several reads that belong together: the lock keeps a stepping thread out between them
  // (each call also takes it, so in a single-threaded sketch this is only a habit of the paper's sketches).
  synchronized (mdl.getLock()) {
    pos = mdl.getMatPosition(name);
    vel = mdl.getMatVelAt(selMat);
    frc = mdl.getMatFrcAt(selMat);
  }
  Vect3D moved = new Vect3D(pos).sub(start[selMat]);
  float x = 12;
  float y = 10;
  text("MODEL  (Tactus " + PhysicalModel.VERSION + ")", x, y);
  text("rate " + mdl.getSimRate() + " steps/s, drawn at " + mdl.getDisplayRate() + " frames/s" + (paused ? ", PAUSED" : ""), x, y + 16);
  text("gravity " + num(mdl.getGravity()) + " along -" + mdl.getGravityDirection() + ", friction " + num(mdl.getFriction()), x, y + 32);
  text("units " + mdl.getParamSystem() + ", bars' knob on subset '" + barKnob.getSubsetName() + "'", x, y + 48);

  x = 12;
  y = 90;
  text("MASS " + selMat + " '" + name + "' (" + mdl.getMatTypeAt(selMat) + ")", x, y);
  text("position " + pos.toString(), x, y + 16);
  text("velocity " + num(vel.x()) + ", " + num(vel.y()) + ", " + num(vel.z()) + " per second", x, y + 32);
  text("force " + num(frc.x) + ", " + num(frc.y) + ", " + num(frc.z) + " (for the next step)", x, y + 48);
  text("moved " + nf((float) moved.norm(), 0, 1) + " from its start (" + nf((float) Math.sqrt(pos.sqDist(start[selMat])), 0, 1) + ")", x, y + 64);
  switch (mdl.getMatTypeAt(selMat)) {
  case Ground3D:
    text("a fixed point: no mass", x, y + 80);
    break;
  case Osc3D:
    text("mass " + num(mdl.getMatMassAt(selMat)) + ", K " + num(mdl.getMatStiffnessAt(selMat)) + ", Z " + num(mdl.getMatDampingAt(selMat)), x, y + 80);
    break;
  default:
    text("mass " + num(mdl.getMatMassAt(selMat)), x, y + 80);
    break;
  }

  x = 600;
  y = 10;
  String link = mdl.getLinkNameAt(selLink);
  text("LINK " + selLink + " '" + link + "' (" + mdl.getLinkTypeAt(selLink) + "), first index of that name: "
    + mdl.getLinkIndex(link), x, y);
  text("K " + num(mdl.getLinkStiffnessAt(selLink)) + ", Z " + num(mdl.getLinkDampingAt(selLink)), x, y + 16);
  text("rest length " + nf((float) mdl.getLinkDRestAt(selLink), 0, 2) + ", length " + nf((float) mdl.getLinkDistanceAt(selLink), 0, 2)
    + ", stretched " + nf((float) mdl.getLinkElongationAt(selLink), 0, 2), x, y + 32);
  Vect3D mid = new Vect3D(mdl.getLinkPos1At(selLink)).add(mdl.getLinkPos2At(selLink)).div(2);
  text("middle at " + mid, x, y + 48);

  textSize(12);
  text("UP/DOWN: mass  LEFT/RIGHT: link  [ ]: link K  ; ': link Z  M: mass x2  K: oscillator K  D: oscillator Z  "
    + "R: mass back to its start", 12, height - 52);
  text("B: retune the bars (subset)  H: reset the handle (by name)  1-9: knob 2 (bars' K)  W: widen knob 2  "
    + "S: rate 1000/2000  SPACE: pause  N: one step  C: clear and rebuild", 12, height - 36);
  text("the hammer swings on its own; the selection walks through the model until you press a key", 12, height - 20);
}

// Four significant digits.
String num(double v) {
  return String.format("%.4g", v);
}

void keyPressed() {
  autoSelect = false;
  int n = mdl.getNumberOfMats();
  int l = mdl.getNumberOfLinks();
  String mat = mdl.getMatNameAt(selMat);
  boolean osc = mdl.getMatTypeAt(selMat) == matModuleType.Osc3D;
  if (keyCode == UP) {
    selMat = (selMat + 1) % n;
  } else if (keyCode == DOWN) {
    selMat = (selMat + n - 1) % n;
  } else if (keyCode == RIGHT) {
    selLink = (selLink + 1) % l;
  } else if (keyCode == LEFT) {
    selLink = (selLink + l - 1) % l;
  } else if (key == '[' || key == ']') {
    mdl.setLinkStiffnessAt(selLink, mdl.getLinkStiffnessAt(selLink) * (key == ']' ? 1.25 : 0.8));
  } else if (key == ';' || key == '\'') {
    mdl.setLinkDampingAt(selLink, mdl.getLinkDampingAt(selLink) * (key == '\'' ? 1.25 : 0.8));
  } else if ((key == 'm' || key == 'M') && mdl.getMatTypeAt(selMat) != matModuleType.Ground3D) {
    if (key == 'M') {
      mdl.setMatMass(mat, mdl.getMatMassAt(selMat) * 2);    // by name
    } else {
      mdl.setMatMassAt(selMat, mdl.getMatMassAt(selMat) / 2); // by index
    }
  } else if ((key == 'k' || key == 'K') && osc) {
    mdl.setMatStiffnessAt(selMat, mdl.getMatStiffnessAt(selMat) * (key == 'K' ? 1.25 : 0.8));
  } else if ((key == 'd' || key == 'D') && osc) {
    mdl.setMatDampingAt(selMat, mdl.getMatDampingAt(selMat) * (key == 'D' ? 1.25 : 0.8));
  } else if (key == 'r' || key == 'R') {
    mdl.setMatPosAt(selMat, start[selMat]);
  } else if (key == 'b' || key == 'B') {
    // the whole subsets at once
    mdl.changeStiffnessParamOfSubset(random(0.002, 0.015), "bars");
    mdl.changeDampingParamOfSubset(0.0002, "bars");
    mdl.changeMassParamOfSubset(1, "bars");
    mdl.changeDistParamOfSubset(25, "strikes");
  } else if (key == 'h' || key == 'H') {
    mdl.setLinkParams("handle", 0.05, 0.002, 200);
    mdl.setLinkStiffness("handle", 0.05);
    mdl.setLinkDamping("handle", 0.002);
    mdl.setLinkDRest("handle", 200);
  } else if (key >= '1' && key <= '9') {
    barKnob.changeParam((key - '1') * 127 / 8);
  } else if (key == 'w' || key == 'W') {
    barKnob.setParam("max", 0.04);
  } else if (key == 's' || key == 'S') {
    mdl.setSimRate(mdl.getSimRate() == 1000 ? 2000 : 1000);
    mdl.setDisplayRate(dispRate);
  } else if (key == ' ') {
    paused = !paused;
  } else if ((key == 'n' || key == 'N') && paused) {
    mdl.computeStep();
  } else if (key == 'c' || key == 'C') {
    build();
  }
}
