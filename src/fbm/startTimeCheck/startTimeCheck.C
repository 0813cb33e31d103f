/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "startTimeCheck.H"
#include "Time.H"
#include "OSspecific.H"
#include "HashSet.H"
#include "Pstream.H"
#include <fstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
    defineTypeNameAndDebug(startTimeCheck, 0);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

bool Foam::fbm::startTimeCheck::endsComplete(const fileName& file)
{
    std::ifstream is(file, std::ios::binary);
    if (!is.good())
    {
        return false;
    }

    // A FoamFile header near the start (after the banner)?
    std::string head(1024, '\0');
    is.read(&head[0], head.size());
    head.resize(is.gcount());
    if (head.find("FoamFile") == std::string::npos)
    {
        return true;
    }

    // The end divider in the last bytes
    is.clear();
    is.seekg(0, std::ios::end);
    const std::streamoff size = is.tellg();
    if (size <= 0)
    {
        return false;
    }
    const std::streamoff n = std::min<std::streamoff>(size, 200);
    std::string tail(n, '\0');
    is.seekg(size - n);
    is.read(&tail[0], n);
    return tail.find("// *****") != std::string::npos;
}


Foam::wordList Foam::fbm::startTimeCheck::fieldFiles(const fileName& dir)
{
    DynamicList<word> names;
    for (const fileName& f : readDir(dir, fileName::FILE, false))
    {
        std::ifstream is(dir/f, std::ios::binary);
        std::string head(1024, '\0');
        is.read(&head[0], head.size());
        head.resize(is.gcount());
        if (f.hasExt("gz") || head.find("FoamFile") != std::string::npos)
        {
            names.append(f.hasExt("gz") ? word(f.lessExt()) : word(f));
        }
    }
    return wordList(names);
}


Foam::wordList Foam::fbm::startTimeCheck::lacks
(
    const fileName& dir,
    const wordList& required
)
{
    DynamicList<word> lack;
    for (const word& name : required)
    {
        const fileName f(dir/name);
        if (isFile(f, false))
        {
            if (!endsComplete(f))
            {
                lack.append(name + " (cut off)");
            }
        }
        else if (!isFile(f + ".gz", false))
        {
            lack.append(name);
        }
    }
    return wordList(lack);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::startTimeCheck::check(const Time& runTime)
{
    // The earlier times of this case (of this processor's part)
    const instantList all(runTime.times());
    DynamicList<instant> earlier;
    for (const instant& t : all)
    {
        if
        (
            t.name() != runTime.constant()
         && t.value() < runTime.value()
         && !t.equal(runTime.value())
        )
        {
            earlier.append(t);
        }
    }

    string message;
    if (earlier.size())
    {
        // What the start time must hold: U, p, uniform/time, and the
        // fields (and body state) of the latest earlier solver-written time
        wordHashSet required;
        required.insert("U");
        required.insert("p");
        required.insert("uniform/time");
        for (label i = earlier.size() - 1; i >= 0; --i)
        {
            const fileName dir(runTime.path()/earlier[i].name());
            if (isFile(dir/"uniform"/"time", false))
            {
                required.insert(fieldFiles(dir));
                if (isFile(dir/"uniform"/"fbmBodies", false))
                {
                    required.insert("uniform/fbmBodies");
                }
                break;
            }
        }
        const wordList names(required.sortedToc());

        const fileName startDir(runTime.timePath());
        const wordList lack(lacks(startDir, names));
        if (lack.size())
        {
            // The latest earlier time that is complete (the initial time
            // needs neither uniform/time nor a body state)
            word lastGood;
            for (label i = earlier.size() - 1; i >= 0 && lastGood.empty(); --i)
            {
                wordList need(names);
                if (i == 0)
                {
                    need.setSize(2);
                    need[0] = "U";
                    need[1] = "p";
                }
                if (lacks(runTime.path()/earlier[i].name(), need).empty())
                {
                    lastGood = earlier[i].name();
                }
            }

            OStringStream os;
            os  << "Start time " << runTime.timeName() << " is incomplete"
                << " (a run killed while writing it?): " << startDir
                << " lacks ";
            forAll(lack, i)
            {
                os  << (i ? ", " : "") << lack[i];
            }
            os  << nl << "    ";
            if (lastGood.empty())
            {
                os  << "No earlier time is complete either.";
            }
            else
            {
                os  << "The last complete time is " << lastGood << ".";
            }
            os  << " Delete the folder " << runTime.timeName()
                << (Pstream::parRun() ? " in every processor* folder" : "")
                << " and run again (startFrom latestTime then continues"
                << " from the time before it)";
            message = os.str();
        }
    }

    // Every processor's finding, reported once
    List<string> messages(Pstream::nProcs());
    messages[Pstream::myProcNo()] = message;
    Pstream::gatherList(messages);
    Pstream::scatterList(messages);
    string report;
    for (const string& m : messages)
    {
        if (!m.empty())
        {
            report += (report.empty() ? "" : "\n") + m;
        }
    }
    if (!report.empty())
    {
        FatalErrorInFunction
            << report.c_str() << exit(FatalError);
    }
}


// ************************************************************************* //
