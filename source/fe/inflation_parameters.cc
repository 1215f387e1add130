#include <greentread/base/parameters.h>
#include <greentread/fe/inflation_parameters.h>

namespace greentread
{
  namespace fe
  {
    void
    InflationParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Inflation");
      prm.declare_entry("Pressure", "2e5", base::RangePattern::non_negative("Pa"),
                        "Inflation pressure P on the inner surface (gauge). Unit: Pa. "
                        "Paper: 2 bar = 2e5 Pa.");
      prm.leave_subsection();
    }



    void
    InflationParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Inflation");
      pressure = prm.get_double("Pressure");
      prm.leave_subsection();
    }
  } // namespace fe
} // namespace greentread
