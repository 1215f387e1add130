#include <greentread/base/exceptions.h>
#include <greentread/contact/tread_pattern_parameters.h>

#include <deal.II/base/utilities.h>

#include <string>

namespace greentread
{
  namespace contact
  {
    void
    TreadPatternParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Tread pattern");
      prm.declare_entry(
        "Pattern", "slick", dealii::Patterns::Selection("slick|blocks|image"),
        "The tread's grooves, which move through the contact patch with the road "
        "(doc/methods/contact.md#tread-patterns): 'slick' (none), 'blocks' (a lateral "
        "groove at the start of every pitch and the 'Circumferential grooves'), "
        "'image' (one pitch's footprint from 'Footprint image', stretched over "
        "each pitch). The carcass stays the axisymmetric ring: the Green's "
        "functions and the modes do not change.");
      prm.declare_entry("Pitch lengths", "0.03",
                        dealii::Patterns::List(dealii::Patterns::Double(0.), 1, 16, ","),
                        "The pitch lengths [m] the 'Pitch sequence' picks from. The "
                        "sequence, repeated round the tyre as many whole times as fit "
                        "best, is scaled by one factor to fill the circumference exactly "
                        "(the run prints the factor).");
      prm.declare_entry("Pitch sequence", "",
                        dealii::Patterns::List(dealii::Patterns::Integer(1, 16), 0, 1000, ","),
                        "The order of the pitches round the tyre, as 1-based indices "
                        "into 'Pitch lengths' (e.g. 1, 2, 3, 2, 1, 3); empty: the first "
                        "length repeated (a uniform pitch).");
      prm.declare_entry("Groove depth", "0.006", dealii::Patterns::Double(0.),
                        "The grooves' depth [m], at most 'Geometry/Tread thickness'.");
      prm.declare_entry("Lateral groove width", "0.005", dealii::Patterns::Double(0.),
                        "With 'blocks': the width [m] of the groove across the tread "
                        "at the start of every pitch (not scaled with the pitch); at "
                        "least one contact rectangle, and shorter than the shortest "
                        "pitch by one. 0: none.");
      prm.declare_entry("Circumferential grooves", "",
                        dealii::Patterns::List(dealii::Patterns::Double(), 0, 16, ","),
                        "With 'blocks': the centres [m] across the tread (0: the "
                        "tread's centre line) of grooves that run round the tyre.");
      prm.declare_entry("Circumferential groove width", "0.008", dealii::Patterns::Double(0.),
                        "With 'blocks': their width [m], at least one contact "
                        "rectangle across.");
      prm.declare_entry("Footprint image", "", dealii::Patterns::Anything(),
                        "With 'image': a PGM file (P2 or P5) of one pitch's footprint, "
                        "rows along the pitch (the first at its start), columns across "
                        "'Footprint width' centred on the tread; a pixel darker than "
                        "half the largest grey is a groove. Every pitch must span at "
                        "least 4 contact rectangles along.");
      prm.declare_entry("Footprint width", "0.12", dealii::Patterns::Double(0.),
                        "With 'image': the width [m] across the tread the image's columns "
                        "span, at most 'Geometry/Tread width'.");
      prm.declare_entry("Compare with slick", "true", dealii::Patterns::Bool(),
                        "With a pattern: each road is also rolled by the slick tyre, "
                        "named '<road> slick', so that its spectra are plotted beside "
                        "the patterned tyre's.");
      prm.declare_entry(
        "Block compliance", "auto", dealii::Patterns::Selection("auto|endless layer|finite blocks"),
        "The tread's local compliance under the contact points: 'endless layer' (as the slick "
        "tyre's), or 'finite blocks' (with 'blocks': what each block adds to it, by a 3D "
        "finite-element model of the block on its undertread, computed when the run starts; "
        "a block's edges and corners are softer, and it is softer on the whole since its "
        "sides bulge; doc/methods/contact.md#tread-patterns). 'auto': finite blocks with "
        "'blocks', the endless layer with 'image'. Finite blocks need 'Contact grid/Solver' "
        "= projected CG (auto chooses it with the ring's own modes).");
      prm.declare_entry("Block mesh size", "0.002", dealii::Patterns::Double(0.),
                        "With finite blocks: the side [m] of the rectangles of the table "
                        "over each block's top, and of its finite-element mesh's cells "
                        "(quadratic bricks). Smaller: finer and slower (the cost grows as "
                        "its cube); benchmarks/tread_pattern measures what it moves.");
      prm.leave_subsection();
    }



    void
    TreadPatternParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Tread pattern");
      pattern       = prm.get("Pattern");
      pitch_lengths = dealii::Utilities::string_to_double(
        dealii::Utilities::split_string_list(prm.get("Pitch lengths")));
      sequence.clear();
      for (const int i : dealii::Utilities::string_to_int(
             dealii::Utilities::split_string_list(prm.get("Pitch sequence"))))
        sequence.push_back(static_cast<unsigned int>(i));
      groove_depth            = prm.get_double("Groove depth");
      lateral_groove_width    = prm.get_double("Lateral groove width");
      circumferential_centres = dealii::Utilities::string_to_double(
        dealii::Utilities::split_string_list(prm.get("Circumferential grooves")));
      circumferential_width = prm.get_double("Circumferential groove width");
      footprint_image       = prm.get("Footprint image");
      footprint_width       = prm.get_double("Footprint width");
      compare_with_slick    = prm.get_bool("Compare with slick");
      block_compliance      = prm.get("Block compliance");
      block_mesh_size       = prm.get_double("Block mesh size");
      prm.leave_subsection();
      for (const unsigned int i : sequence)
        if (i > pitch_lengths.size())
          throw InputError("parameter 'Tread pattern/Pitch sequence' names pitch " +
                           std::to_string(i) + "; allowed: 1 to " +
                           std::to_string(pitch_lengths.size()) + " (the 'Pitch lengths' given)");
      for (const double p : pitch_lengths)
        if (!(p > 0.))
          throw InputError("parameter 'Tread pattern/Pitch lengths' gives " + format_number(p) +
                           " m; allowed: lengths above 0");
      if (block_compliance == "finite blocks" && pattern != "blocks")
        throw InputError("parameter 'Tread pattern/Block compliance' = finite blocks needs "
                         "'Tread pattern/Pattern' = blocks; it is '" +
                         pattern + "' (allowed with it: auto, endless layer)");
      if (finite_blocks() && !(block_mesh_size > 0.))
        throw InputError("parameter 'Tread pattern/Block mesh size' = " +
                         format_number(block_mesh_size) + " m; allowed: above 0");
      if (pattern == "image" && footprint_image.empty())
        throw InputError("parameter 'Tread pattern/Footprint image' is empty; 'Pattern' = image "
                         "needs a PGM file");
    }
  } // namespace contact
} // namespace greentread
